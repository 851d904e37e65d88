namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// One view's material passes at the colour's supersampled size, rows bottom-up, in the layouts of RawFrame's
    /// <c>MaterialAlbedo</c> … <c>MaterialSupported</c>: linear values, 0 wherever no supported shader covers the sample.
    /// A pass that was not asked for is null.
    /// </summary>
    public sealed class MaterialPassResult
    {
        /// <summary>Linear base colour, 4 floats per sample (A = 1 where covered).</summary>
        public float[] Albedo { get; internal set; }

        /// <summary>Metallic, 1 float per sample; 0 for specular-setup materials.</summary>
        public float[] Metallic { get; internal set; }

        /// <summary>Perceptual roughness = 1 − smoothness, 1 float per sample.</summary>
        public float[] Roughness { get; internal set; }

        /// <summary>Linear specular colour (specular setup only), 4 floats per sample.</summary>
        public float[] Specular { get; internal set; }

        /// <summary>Linear emission (may exceed 1), 4 floats per sample.</summary>
        public float[] Emission { get; internal set; }

        /// <summary>255 where a supported shader covers the sample, else 0; 1 byte per sample.</summary>
        public byte[] Supported { get; internal set; }
    }
}
