using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The lens the dataset's images are taken through (issue 27): none (a pinhole, the default), OpenCV
    /// radial-tangential (k1, k2, p1, p2, optional k3) or OpenCV fisheye (k1…k4), on the normalised coordinates of
    /// <see cref="LensDistortion"/> (y down). The capture renders a wide pinhole view (<see cref="LensPinholeCover"/>)
    /// and resamples it through this lens (<see cref="LensResampler"/>); the transforms files carry the model and
    /// coefficients under the keys the loaders read (<see cref="TransformsLensKeys"/>).
    /// </summary>
    [Serializable]
    public sealed class LensSettings
    {
        /// <summary>Config key of the whole object in a settings file.</summary>
        public const string Key = "lens";

        /// <summary>"none", "opencv" or "opencv_fisheye" (config names; <see cref="ModelNames"/>).</summary>
        public string Model = ModelNames.None;

        public double K1, K2, K3, K4, P1, P2;

        /// <summary>Whether the images are distorted (any model but none).</summary>
        public bool Enabled => !string.Equals(Model ?? ModelNames.None, ModelNames.None, StringComparison.OrdinalIgnoreCase);

        public LensSettings Clone() => (LensSettings)MemberwiseClone();

        /// <summary>
        /// The lens model, or null for none (and for an OpenCV lens whose coefficients are all 0, which is a pinhole).
        /// Throws <see cref="InvalidParameterException"/> for an unknown model or coefficients the model does not have;
        /// <see cref="LensSettingsValidator"/> reports the same problems under the config keys first.
        /// </summary>
        public LensDistortion ToDistortion()
        {
            if (!Enabled) return null;
            if (!ModelNames.TryParse(Model, out var model))
                throw new InvalidParameterException(new[] { ModelNames.Unknown(Model) });
            var lens = new LensDistortion(model, K1, K2, K3, K4, P1, P2);
            return lens.IsPinhole ? null : lens;
        }

        /// <summary>The config names of the models.</summary>
        public static class ModelNames
        {
            public const string None = "none";
            public const string OpenCv = "opencv";
            public const string Fisheye = "opencv_fisheye";

            public static string List => "\"none\", \"opencv\", \"opencv_fisheye\"";

            public static bool TryParse(string name, out LensModel model)
            {
                model = LensModel.OpenCv;
                var n = (name ?? "").Trim().ToLowerInvariant();
                if (n == OpenCv) return true;
                if (n == Fisheye) { model = LensModel.OpenCvFisheye; return true; }
                return false;
            }

            public static bool IsKnown(string name)
            {
                var n = (name ?? "").Trim().ToLowerInvariant();
                return n == None || n == OpenCv || n == Fisheye;
            }

            internal static ValidationProblem Unknown(string name) =>
                new ValidationProblem("lens.model", "\"" + name + "\"", "is not a lens model.",
                    "Use one of " + List + " (COLMAP/nerfstudio OPENCV and OPENCV_FISHEYE).");
        }
    }
}
