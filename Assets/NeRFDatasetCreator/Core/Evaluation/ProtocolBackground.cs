namespace NerfDatasetCreator
{
    /// <summary>
    /// The background a dataset is meant to be trained and scored on, as 8-bit sRGB: what exports for trainers that
    /// drop alpha composite the RGBA images over (<see cref="AlphaCompositing"/>). Read from the dataset's
    /// <c>eval_protocol.json</c> (<see cref="EvalProtocolFile"/>) first; a dataset without one (nerf_synthetic, or
    /// captured before issue 35) gets the protocol it would have been written with: its own solid colour when it has
    /// one, else white (nerf_synthetic's evaluation). A protocol of random backgrounds is scored over white, so white is
    /// what an export that must drop alpha composites over.
    /// </summary>
    public static class ProtocolBackground
    {
        /// <summary>The protocol's background for the dataset in <paramref name="datasetRoot"/>: its name ("white", "black", "dataset") and colour.</summary>
        /// <exception cref="InvalidParameterException">The dataset's eval_protocol.json is not a protocol (named, with the key).</exception>
        public static (string Name, byte R, byte G, byte B) For(string datasetRoot)
        {
            var protocol = EvalProtocolFile.Read(datasetRoot) ?? EvalProtocolFile.Derived(datasetRoot);
            return (protocol.EvaluationBackgroundName, protocol.R, protocol.G, protocol.B);
        }
    }
}
