using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The lens setting's problems, each under its config key (<c>lens.model</c>, <c>lens.k1</c> …), and its plan
    /// warnings. Refused: an unknown model, a coefficient that is not finite or not the model's, a lens that folds over
    /// inside the frame, a wide render beyond <see cref="LensPinholeCover"/>'s caps or the GPU's texture size, and the
    /// lenses instant-ngp would read wrongly from the transforms files when it is among the loaders.
    /// </summary>
    public static class LensSettingsValidator
    {
        public static IReadOnlyList<ValidationProblem> Validate(DatasetSettings settings)
        {
            var problems = new List<ValidationProblem>();
            var lens = settings.Lens;
            if (lens == null) return problems;
            if (!lens.Enabled)
            {
                // Coefficients without a model would be dropped without a word: a silently wrong lens.
                if (lens.K1 != 0 || lens.K2 != 0 || lens.K3 != 0 || lens.K4 != 0 || lens.P1 != 0 || lens.P2 != 0)
                    problems.Add(new ValidationProblem("lens.model", "\"" + (lens.Model ?? LensSettings.ModelNames.None) + "\"",
                        "is none, but lens gives distortion coefficients.", "Set lens.model to \"opencv\" or \"opencv_fisheye\", or remove the coefficients."));
                return problems;
            }
            if (!LensSettings.ModelNames.TryParse(lens.Model, out var model))
            {
                problems.Add(LensSettings.ModelNames.Unknown(lens.Model));
                return problems;
            }
            void Finite(string key, double value)
            {
                if (double.IsNaN(value) || double.IsInfinity(value))
                    problems.Add(new ValidationProblem("lens." + key, ValidationProblem.Format(value), "is not a finite number.", "Write the lens coefficient as a number (0 when the lens has none)."));
            }
            Finite("k1", lens.K1); Finite("k2", lens.K2); Finite("k3", lens.K3); Finite("k4", lens.K4); Finite("p1", lens.P1); Finite("p2", lens.P2);
            if (model == LensModel.OpenCv && lens.K4 != 0)
                problems.Add(new ValidationProblem("lens.k4", ValidationProblem.Format(lens.K4), "is not a coefficient of the \"opencv\" model (k1, k2, p1, p2, k3).",
                    "Set lens.model to \"opencv_fisheye\" for a fisheye, or remove k4."));
            if (model == LensModel.OpenCvFisheye && lens.P1 != 0)
                problems.Add(new ValidationProblem("lens.p1", ValidationProblem.Format(lens.P1), "is not a coefficient of the \"opencv_fisheye\" model (k1…k4).",
                    "Set lens.model to \"opencv\" for a radial-tangential lens, or remove p1."));
            if (model == LensModel.OpenCvFisheye && lens.P2 != 0)
                problems.Add(new ValidationProblem("lens.p2", ValidationProblem.Format(lens.P2), "is not a coefficient of the \"opencv_fisheye\" model (k1…k4).",
                    "Set lens.model to \"opencv\" for a radial-tangential lens, or remove p2."));
            if (problems.Count > 0) return problems;

            // Sub-frames average in the wide frame first, so a global shutter composes with a lens; a rolling shutter does
            // not yet: a row of the distorted image is a curve in the wide render, so each row's exposure time would be wrong.
            if (ShutterPlanning.IsOn(settings) && settings.MotionBlur.Readout > 0)
                problems.Add(new ValidationProblem("lens", "\"" + lens.Model + "\"", "cannot be combined with a rolling shutter (motionBlur.readout " +
                    ValidationProblem.Format(settings.MotionBlur.Readout) + ") yet: the distorted image's rows are curves in the wide render, so each row's exposure time would be wrong.",
                    "Set motionBlur.readout to 0 (a global shutter works with a lens), or remove the lens."));

            // instant-ngp reads the transforms files as written (nerf_loader.cu read_lens, see NgpWriter.Refusal).
            if ((settings.Loaders & TargetLoaders.InstantNgp) != 0)
            {
                var refusal = NgpWriter.Refusal(new LensDistortion(model, lens.K1, lens.K2, lens.K3, lens.K4, lens.P1, lens.P2));
                if (refusal != null)
                    problems.Add(new ValidationProblem("lens." + (refusal.Field == "k3" ? "k3" : "model"), refusal.Value, refusal.Reason,
                        "Remove \"instant-ngp\" from loaders (nerfstudio and COLMAP hold this lens), or " + (refusal.Field == "k3" ? "set k3 to 0." : "give the fisheye a coefficient.")));
            }

            // The wide render: only when the frame itself is valid (its own keys report it otherwise).
            if (problems.Count > 0 || !(settings.Camera?.VerticalFovDegrees > 0 && settings.Camera.VerticalFovDegrees < 180)) return problems;
            if (settings.Width < DatasetSettings.MinSize || settings.Width > DatasetSettings.MaxSize || settings.Height < DatasetSettings.MinSize || settings.Height > DatasetSettings.MaxSize) return problems;
            try
            {
                var cover = LensCapture.WideRender(settings.Lens.ToDistortion(), settings.Intrinsics());
                if (cover == null) return problems;
                var k = Math.Max(1, settings.Supersampling);
                // The capture renders the wide view at the output's limits: DatasetSettings.MaxSize per side (the capture
                // options' own), times the supersampling within a render texture's MaxRenderSize.
                var largest = Math.Max(cover.Width, cover.Height);
                var side = largest * (long)k;
                if (largest > DatasetSettings.MaxSize || side > DatasetSettings.MaxRenderSize)
                    problems.Add(new ValidationProblem("lens", lens.ToDistortion().Describe(),
                        "needs a wide pinhole render of " + Text(cover.Width) + " × " + Text(cover.Height) + " pixels to cover the " + Text(settings.Width) + " × " + Text(settings.Height) +
                        " frame; at supersampling " + Text(k) + " that is " + side.ToString(CultureInfo.InvariantCulture) + " pixels across, beyond the " + Text(DatasetSettings.MaxSize) +
                        " a side may have or the " + Text(DatasetSettings.MaxRenderSize) + " a render texture can have.",
                        "Lower the supersampling or the resolution, or use a milder lens."));
            }
            catch (InvalidParameterException e)
            {
                foreach (var p in e.Problems) problems.Add(new ValidationProblem("lens", p.Value, p.Reason, p.Fix));
            }
            return problems;
        }

        /// <summary>
        /// Plan warnings: the loaders that read only <c>camera_angle_x</c> (the original NeRF code, 3DGS's Blender reader)
        /// train as if the distorted images were pinhole images.
        /// </summary>
        public static IEnumerable<ValidationProblem> Warnings(DatasetSettings settings)
        {
            var lens = settings.Lens;
            if (lens == null || !lens.Enabled || !LensSettings.ModelNames.IsKnown(lens.Model)) yield break;
            if ((settings.Loaders & TargetLoaders.Nerf) != 0)
                yield return new ValidationProblem("lens", lens.Model,
                    "is ignored by the original NeRF loaders (bmild/nerf load_blender.py, nerf-pytorch): they read camera_angle_x only, so they would train on distorted images as if they were pinhole ones.",
                    "Train with instant-ngp (reads the transforms files' k1…p2) or nerfstudio (nerf-dataset convert --to nerfstudio), or remove \"nerf\" from loaders.");
            if ((settings.Loaders & TargetLoaders.GaussianSplatting) != 0)
                yield return new ValidationProblem("lens", lens.Model,
                    "is ignored by 3DGS's Blender reader (scene/dataset_readers.py readCamerasFromTransforms reads camera_angle_x only), and its COLMAP reader accepts only undistorted PINHOLE cameras.",
                    "Train Gaussians with gsplat or splatfacto (nerf-dataset convert --to colmap or --to nerfstudio), or undistort first; or remove \"3dgs\" from loaders.");
        }

        static string Text(long v) => v.ToString(CultureInfo.InvariantCulture);
    }
}
