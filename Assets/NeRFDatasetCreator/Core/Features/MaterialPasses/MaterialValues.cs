namespace NerfDatasetCreator
{
    /// <summary>
    /// Turns one material pass as read back (RGBA half floats, the values the shader wrote) and its coverage pass (RGBA
    /// bytes: R ≥ 128 where a supported shader covers the sample, G ≥ 128 where that material is in a specular setup)
    /// into RawFrame's material arrays: linear, 0 wherever no supported shader covers the sample (never a guess).
    /// A Gamma colour-space project's colours are gamma-space in the shader, and are decoded with the sRGB curve
    /// (extended above 1 for emission); scalars (metallic, smoothness) are used by the shader as they are in either space.
    /// </summary>
    public static class MaterialValues
    {
        /// <summary>
        /// A colour pass (base colour, specular, emission): 4 floats per sample, A = 1 where covered. With
        /// <paramref name="specularSetupOnly"/>, samples of metallic-workflow materials are 0 (they have no specular colour).
        /// </summary>
        public static float[] Colour(ushort[] rgbaHalf, byte[] coverage, bool gammaProject, bool specularSetupOnly)
        {
            var n = coverage.Length / 4;
            var result = new float[4 * n];
            for (var i = 0; i < n; i++)
            {
                if (coverage[4 * i] < 128) continue;
                if (specularSetupOnly && coverage[4 * i + 1] < 128) continue;
                for (var c = 0; c < 3; c++)
                {
                    var v = HalfFloat.ToFloat(rgbaHalf[4 * i + c]);
                    result[4 * i + c] = gammaProject ? (float)Srgb.DecodeExact(v) : v;
                }
                result[4 * i + 3] = 1f;
            }
            return result;
        }

        /// <summary>
        /// A scalar pass from its R channel: metallic (0 for specular-setup materials: URP's Lit reports 1 there,
        /// LitInput.hlsl InitializeStandardLitSurfaceData, which is no metallic value) or, with <paramref name="roughness"/>,
        /// perceptual roughness = 1 − smoothness. 1 float per sample.
        /// </summary>
        public static float[] Scalar(ushort[] rgbaHalf, byte[] coverage, bool roughness)
        {
            var n = coverage.Length / 4;
            var result = new float[n];
            for (var i = 0; i < n; i++)
            {
                if (coverage[4 * i] < 128) continue;
                var v = HalfFloat.ToFloat(rgbaHalf[4 * i]);
                if (roughness) result[i] = MaterialShaderSupport.RoughnessFromSmoothness(v);
                else result[i] = coverage[4 * i + 1] >= 128 ? 0f : v;
            }
            return result;
        }
    }
}
