namespace NerfDatasetCreator
{
    /// <summary>
    /// The analytic scene's materials (contract of issue 38), which the material passes of an analytic dataset
    /// (<see cref="AnalyticDataset.Options.Materials"/>, <c>nerf-dataset demo --preset materials</c>) must show exactly:
    /// the base colour is the object's colour (<see cref="AnalyticScene.ColourOf(AnalyticScene.Sphere, Vector3d)"/>, its
    /// checker included) read as linear; metallic, perceptual roughness, specular colour and emission are constants per
    /// object, by instance id (<see cref="AnalyticScene.Trace(Vector3d, Vector3d, double, out double, out Vector3d, out double[], out double, out int)"/>:
    /// 1 Ball, 2 Glass, 3 Slab, 4 the demo's Crate). The values differ from object to object and metallic from roughness
    /// on each, so a swapped or misplaced pass shows; the glass is the one specular-setup shader and the slab the one
    /// emitter, above 1 in one channel so that the EXR's range shows.
    /// </summary>
    public static class AnalyticMaterials
    {
        /// <summary>The shader names the analytic capture records (dataset_config.json <c>materials.supported_shaders</c>).</summary>
        public const string MetallicShader = "Analytic/Metallic", SpecularShader = "Analytic/Specular";

        static readonly double[] Black = { 0, 0, 0 };

        /// <summary>Metallic of the object with instance id <paramref name="id"/> (0 for none).</summary>
        public static double Metallic(int id) => id == 1 ? 0.6 : id == 4 ? 1.0 : 0.0;

        /// <summary>Perceptual roughness (1 − smoothness) of the object with instance id <paramref name="id"/>.</summary>
        public static double Roughness(int id) => id == 1 ? 0.4 : id == 2 ? 0.1 : id == 3 ? 0.85 : id == 4 ? 0.3 : 0.0;

        /// <summary>Specular colour (linear): the glass's (a specular-setup shader); 0 for the metallic-setup objects.</summary>
        public static double[] Specular(int id) => id == 2 ? new[] { 0.25, 0.5, 0.75 } : Black;

        /// <summary>Emission (linear, may exceed 1): the slab's; 0 elsewhere.</summary>
        public static double[] Emission(int id) => id == 3 ? new[] { 1.5, 0.75, 0.25 } : Black;

        /// <summary>The facts a capture of the analytic scene records (every object's shader is read exactly).</summary>
        public static MaterialCaptureFacts Facts() =>
            new MaterialCaptureFacts(MaterialCaptureFacts.Analytic, new[] { MetallicShader, SpecularShader }, null);

        /// <summary>
        /// Fills <paramref name="frame"/>'s material arrays at sample <paramref name="p"/> for the first surface along the ray
        /// (<paramref name="id"/>, its colour <paramref name="colour"/>): what the material passes render there, supported.
        /// </summary>
        internal static void Sample(RawFrame frame, int p, int id, double[] colour)
        {
            for (var c = 0; c < 3; c++)
            {
                frame.MaterialAlbedo[p * 4 + c] = (float)colour[c];
                frame.MaterialSpecular[p * 4 + c] = (float)Specular(id)[c];
                frame.MaterialEmission[p * 4 + c] = (float)Emission(id)[c];
            }
            frame.MaterialMetallic[p] = (float)Metallic(id);
            frame.MaterialRoughness[p] = (float)Roughness(id);
            frame.MaterialSupported[p] = 255;
        }
    }
}
