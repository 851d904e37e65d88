namespace NerfDatasetCreator
{
    /// <summary>
    /// The labels pass's readback as the raw frame's id channel: 4 bytes per sample, the instance id's low and high byte
    /// first (the Unity layer's RendererLabelIds encoding; Documentation~/maintainers/labels-capture.md), then the class
    /// id's, which the writer does not need (it maps instances to classes through the label table).
    /// </summary>
    public static class LabelsPassIds
    {
        [System.ThreadStatic] static ushort[] ids;

        /// <summary>
        /// The instance id of each sample of <paramref name="labels"/>, into this thread's buffer: the caller hands the frame to
        /// <see cref="ViewPipeline.Write"/>, which has encoded the maps before it returns, so the next view may reuse it.
        /// </summary>
        public static ushort[] InstanceIds(byte[] labels)
        {
            var samples = labels.Length / 4;
            if (ids == null || ids.Length != samples) ids = new ushort[samples];
            for (var i = 0; i < samples; i++) ids[i] = (ushort)(labels[i * 4] | (labels[i * 4 + 1] << 8));
            return ids;
        }
    }
}
