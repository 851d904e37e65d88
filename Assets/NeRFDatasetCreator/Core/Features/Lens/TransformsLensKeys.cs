using Newtonsoft.Json;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The lens keys a capture writes at the top of each transforms file — the keys <see cref="TransformsLens"/> reads
    /// back and convert carries: nerfstudio's <c>camera_model</c> (<c>OPENCV</c> / <c>OPENCV_FISHEYE</c>) and
    /// instant-ngp's <c>is_fisheye</c>, then the coefficients under nerfstudio's and instant-ngp's shared names. OPENCV
    /// writes k1 k2 p1 p2 (and k3 when non-zero: instant-ngp, which reads these files as they are, would store p1 over
    /// it, so settings refuse k3 with instant-ngp among the loaders); the fisheye writes k1…k4 and never p1/p2 (instant-ngp
    /// would store them over k3, k4). Sources: Documentation~/maintainers/lens-distortion.md.
    /// </summary>
    public static class TransformsLensKeys
    {
        /// <summary>The keys of <paramref name="settings"/>' lens; none for a pinhole capture or without settings.</summary>
        public static void Write(JsonWriter w, DatasetSettings settings) => Write(w, settings?.Lens?.ToDistortion());

        public static void Write(JsonWriter w, LensDistortion lens)
        {
            if (lens == null) return;
            w.WritePropertyName("camera_model"); w.WriteValue(lens.CameraModelName);
            if (lens.Model == LensModel.OpenCvFisheye)
            {
                w.WritePropertyName("is_fisheye"); w.WriteValue(true);
                JsonNumbers.Number(w, "k1", lens.K1);
                JsonNumbers.Number(w, "k2", lens.K2);
                JsonNumbers.Number(w, "k3", lens.K3);
                JsonNumbers.Number(w, "k4", lens.K4);
                return;
            }
            JsonNumbers.Number(w, "k1", lens.K1);
            JsonNumbers.Number(w, "k2", lens.K2);
            JsonNumbers.Number(w, "p1", lens.P1);
            JsonNumbers.Number(w, "p2", lens.P2);
            if (lens.K3 != 0) JsonNumbers.Number(w, "k3", lens.K3);
        }
    }
}
