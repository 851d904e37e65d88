namespace NerfDatasetCreator
{
    /// <summary>
    /// A lens's stage for the material passes: each distorted sample takes the nearest wide sample's values
    /// (<see cref="LensResampler.ResampleNearest{T}"/>), never a blend — a material parameter blended across an edge
    /// would be a value no surface has, as for normals — and the k×k coverage-weighted average after it
    /// (<see cref="MaterialPassResolve"/>) does the anti-aliasing, as without a lens.
    /// </summary>
    public static class MaterialPassLens
    {
        /// <summary>Copies <paramref name="wide"/>'s material arrays, resampled, onto <paramref name="distorted"/> (its resample by <paramref name="lens"/>).</summary>
        public static void Carry(LensResampler lens, RawFrame wide, RawFrame distorted)
        {
            if (wide.MaterialSupported == null) return;
            int k = wide.Supersampling;
            long n = (long)distorted.Width * distorted.Height;
            float[] Floats(float[] source, int per)
            {
                if (source == null) return null;
                var output = new float[n * per];
                lens.ResampleNearest(source, per, output, k);
                return output;
            }
            distorted.MaterialAlbedo = Floats(wide.MaterialAlbedo, 4);
            distorted.MaterialMetallic = Floats(wide.MaterialMetallic, 1);
            distorted.MaterialRoughness = Floats(wide.MaterialRoughness, 1);
            distorted.MaterialSpecular = Floats(wide.MaterialSpecular, 4);
            distorted.MaterialEmission = Floats(wide.MaterialEmission, 4);
            var supported = new byte[n];
            lens.ResampleNearest(wide.MaterialSupported, 1, supported, k);
            distorted.MaterialSupported = supported;
        }
    }
}
