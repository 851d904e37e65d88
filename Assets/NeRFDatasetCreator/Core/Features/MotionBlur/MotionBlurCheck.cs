using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <b>motion blur</b>: the blurred image is the sharp one seen over the recorded shutter. The sharp image's alpha
    /// (at the mid pose, with its depth) is carried to the poses of the interval — instant-ngp's own interpolation
    /// between <c>transform_matrix_start</c> and <c>_end</c> at each row's time from <c>rolling_shutter</c>
    /// (<see cref="PoseInterpolation.Lerp(Matrix4x4d, Matrix4x4d, double)"/>) — at <see cref="Samples"/> times, and the
    /// average is compared with the blurred image's alpha. A frame with a sharp image but no start/end keys is taken as
    /// unmoving. A blur written without its keys, or keys of another interval, leaves the two apart.
    /// </summary>
    public sealed class MotionBlurCheck : IViewCheck
    {
        /// <summary>
        /// Largest mean |α_blurred − α_predicted| over the pixels either covers (α &gt; 2 %). The prediction moves whole
        /// pixels with one depth each and misses what the mid pose does not see, so exact data stays near 1–3 % at the
        /// edges (the analytic test's clean figure is in Documentation~/maintainers/motion-blur.md); a missing or wrong
        /// interval moves every blurred edge.
        /// </summary>
        public const double MaxMeanDifference = 0.06;

        /// <summary>Times through the interval the sharp alpha is carried to.</summary>
        public const int Samples = 16;

        public string Name => "motion blur";

        int _views, _bad, _noDepth, _dynamic;
        double _worst;

        /// <summary>Reads a frame's motion blur keys into <paramref name="view"/> (for <see cref="CheckDatasetReader"/>).</summary>
        internal static void ReadKeys(DatasetFrame frame, CheckView view, string fileName, int index, List<DatasetProblem> problems)
        {
            var sharp = frame.Existing(MotionBlurKeys.SharpPath);
            if (sharp != null)
            {
                view.BlurredFile = view.ColourFile;
                view.ColourFile = sharp;
            }
            var shutter = frame.Shutter;
            foreach (var (key, present, written) in new[] { (MotionBlurKeys.Start, shutter.HasStart, shutter.Start), (MotionBlurKeys.End, shutter.HasEnd, shutter.End) })
            {
                if (!present) continue;
                if (!CheckDatasetReader.TryPose(written, out var pose, out var why))
                {
                    problems.Add(new DatasetProblem(CheckDatasetReader.CheckName, fileName, index, key + " " + why));
                    continue;
                }
                foreach (var poseProblem in DatasetValidator.PoseProblems(pose))
                    problems.Add(new DatasetProblem(CheckDatasetReader.CheckName, fileName, index, key + ": " + poseProblem));
                if (key == MotionBlurKeys.Start) view.ShutterStart = pose;
                else view.ShutterEnd = pose;
            }
            view.RollingShutter = shutter.RollingShutter;
        }

        public void View(CheckView view, CheckImages images, List<DatasetProblem> problems)
        {
            if (images.BlurredAlpha == null || images.Alpha == null) return;
            if (images.Depth == null)
            {
                _noDepth++;
                return;
            }
            if (view.Time != null)
            {
                // The content moves over the shutter too, which the poses do not describe.
                _dynamic++;
                return;
            }
            _views++;
            int w = images.Width, h = images.Height;
            var start = view.ShutterStart ?? view.CameraToWorld;
            var end = view.ShutterEnd ?? view.CameraToWorld;
            // Without rolling_shutter instant-ngp uses t = 0 (the start pose) for every ray; a frame with start and end
            // keys but no vector is read the way this plugin writes one: [0, 0, 0, 1].
            var rs = view.RollingShutter ?? new[] { 0.0, 0.0, 0.0, 1.0 };
            var predicted = new double[w * h];
            var poses = new CheckCamera[Samples];
            var mid = view.Camera;
            for (var y = 0; y < h; y++)
            {
                var v = (y + 0.5) / h;
                // The cameras of this row's times (rows differ only with a rolling shutter; cached per row otherwise).
                if (y == 0 || rs[2] != 0)
                    for (var j = 0; j < Samples; j++)
                    {
                        var t = rs[0] + rs[1] * 0.5 + rs[2] * v + rs[3] * (j + 0.5) / Samples;
                        poses[j] = mid.At(PoseInterpolation.Lerp(start, end, t));
                    }
                for (var x = 0; x < w; x++)
                {
                    var i = y * w + x;
                    var a = images.Alpha[i] / 255.0;
                    if (a == 0) continue;
                    var z = DepthNear(images.Depth, w, h, x, y) * view.DepthScale;
                    if (!(z > 0)) continue; // coverage the depth does not reach: left out of the prediction
                    mid.BackProject(x + 0.5, y + 0.5, z, out var px, out var py, out var pz);
                    for (var j = 0; j < Samples; j++)
                        if (poses[j].Project(px, py, pz, out var u2, out var v2, out _))
                            Splat(predicted, w, h, u2 - 0.5, v2 - 0.5, a / Samples);
                }
            }
            double sum = 0;
            var count = 0;
            for (var i = 0; i < predicted.Length; i++)
            {
                var b = images.BlurredAlpha[i] / 255.0;
                var p = Math.Min(1, predicted[i]);
                if (b <= 0.02 && p <= 0.02) continue;
                sum += Math.Abs(b - p);
                count++;
            }
            var mean = count == 0 ? 0 : sum / count;
            if (mean > _worst) _worst = mean;
            if (mean > MaxMeanDifference)
            {
                _bad++;
                problems.Add(new DatasetProblem(Name, "./" + view.BlurredFile, view.Frame,
                    "differs from ./" + view.ColourFile + " seen over the recorded shutter by " + CheckFigures.Percent(mean) + " of coverage on average (above " +
                    CheckFigures.Percent(MaxMeanDifference) + ")" + (view.ShutterStart == null || view.ShutterEnd == null
                        ? ": the frame has no transform_matrix_start/_end, so its blur is not recorded."
                        : ": transform_matrix_start/_end or rolling_shutter do not describe the motion the image shows.")));
            }
        }

        /// <summary>The pixel's depth, or a neighbour's for an edge pixel whose centre misses the surface its coverage touches.</summary>
        static double DepthNear(ushort[] depth, int w, int h, int x, int y)
        {
            if (depth[y * w + x] != 0) return depth[y * w + x];
            for (var dy = -1; dy <= 1; dy++)
                for (var dx = -1; dx <= 1; dx++)
                {
                    int xx = x + dx, yy = y + dy;
                    if (xx >= 0 && yy >= 0 && xx < w && yy < h && depth[yy * w + xx] != 0) return depth[yy * w + xx];
                }
            return 0;
        }

        static void Splat(double[] image, int w, int h, double x, double y, double value)
        {
            var x0 = (int)Math.Floor(x);
            var y0 = (int)Math.Floor(y);
            double fx = x - x0, fy = y - y0;
            Add(image, w, h, x0, y0, value * (1 - fx) * (1 - fy));
            Add(image, w, h, x0 + 1, y0, value * fx * (1 - fy));
            Add(image, w, h, x0, y0 + 1, value * (1 - fx) * fy);
            Add(image, w, h, x0 + 1, y0 + 1, value * fx * fy);
        }

        static void Add(double[] image, int w, int h, int x, int y, double value)
        {
            if (x >= 0 && y >= 0 && x < w && y < h) image[y * w + x] += value;
        }

        public DatasetCheckResult Finish()
        {
            if (_views == 0)
                return DatasetCheckResult.Skip(Name, _noDepth > 0 ? "the blurred views have no depth PNG to carry the sharp image along the shutter"
                    : _dynamic > 0 ? "a dynamic dataset: its content moves over the shutter, which the poses do not describe"
                    : "no view is motion-blurred (no sharp_path)");
            return new DatasetCheckResult(Name, _bad > 0 ? DatasetCheckStatus.Failed : DatasetCheckStatus.Passed,
                _views + " blurred views, worst mean difference " + CheckFigures.Percent(_worst), "≤ " + CheckFigures.Percent(MaxMeanDifference) + " of coverage",
                _bad > 0 ? _bad + " problem(s)" : null);
        }
    }
}
