using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// gsplat's <c>normalize_world_space</c> (its default), recomputed: simple_trainer's COLMAP parser moves the world by
    /// transform = T3·T2·T1 and saves it nowhere (nerfstudio-project/gsplat at 90d7b4b, examples/datasets/colmap.py lines
    /// 276–304; normalize.py lines 19–112). T1 = similarity_from_cameras (up from the cameras' mean −y axis, centre the
    /// median of the optical axes' closest points to the origin, scale 1 / median camera distance); T2 =
    /// align_principal_axes of the T1 points (eigenvectors of their covariance, largest first, a right-handed basis,
    /// about their median); T3 = a 180° turn about x when the median z exceeds the mean z. The eigenvectors' signs are
    /// numpy's (LAPACK's) choice: of the four right-handed sign choices, the one whose transformed COLMAP points best
    /// match the PLY's centres is taken, and said.
    /// </summary>
    public static class GsplatNormalisation
    {
        /// <param name="assumedDefault">cfg.yml has no normalize_world_space key (gsplat's default is on).</param>
        public static TrainedModel Place(string folder, string ply, string dataDir, bool assumedDefault, List<string> notes)
        {
            var (resolved, how) = ResolveDataDir(folder, dataDir);
            var sparse = ColmapSparseModel.FolderOf(resolved);
            if (sparse == null)
                throw TrainedModel.Refuse(TrainerFolders.GsplatConfig + ": data_dir", resolved, "has no sparse/0 or sparse folder, so gsplat's normalisation cannot be recomputed.",
                    "Restore the COLMAP model gsplat trained on, or train again with --no-normalize-world-space (the splat then stays in the dataset's frame).");
            var model = ColmapSparseModel.Read(sparse);
            if (model.Poses.Count == 0 || model.Points.Count < 4)
                throw TrainedModel.Refuse(TrainerFolders.GsplatConfig + ": data_dir", sparse, "holds " + model.Poses.Count + " images and " + model.Points.Count + " points; gsplat's normalisation needs cameras and points.",
                    "Pass the result folder of a run on a COLMAP model with points (convert --to colmap writes one).");
            var candidates = Candidates(model);
            var centres = GaussianPly.ReadCentres(ply, 0).Centres;
            var scored = candidates.Select(c => (c.Transform, c.Signs, Score: Match(c.Transform, model.Points, centres)))
                .OrderBy(c => c.Score.Median).ThenBy(c => c.Score.Mean).ToList();
            var best = scored[0];
            var next = scored.Count > 1 ? scored[1] : scored[0];
            var size = Size(model.Points.Select(best.Transform.MultiplyPoint).ToList());
            notes.Add("gsplat normalised the world (normalize_world_space " + (assumedDefault ? "not in cfg.yml: gsplat's default, on" : "on") + "): recomputed from " + model.Source +
                      ", data_dir " + how + ".");
            var tie = Math.Abs(next.Score.Median - best.Score.Median) <= 1e-6 * size && Math.Abs(next.Score.Mean - best.Score.Mean) <= 1e-6 * size;
            notes.Add("the principal axes' signs are numpy's choice: chose " + best.Signs + ", whose transformed COLMAP points lie a median " + Show(best.Score.Median) +
                      " (mean " + Show(best.Score.Mean) + ") from the PLY's nearest centres; the next best choice " + next.Signs + ": median " + Show(next.Score.Median) + ", mean " + Show(next.Score.Mean) + "." +
                      (tie ? " The two fit equally (the points look the same after a half turn), so either places the splat's centres alike." : ""));
            return new TrainedModel(TrainedModel.Gsplat, folder, ply, best.Transform,
                "gsplat's normalised world (recomputed exactly as its COLMAP parser does, principal-axis signs " + best.Signs + ")", notes);
        }

        /// <summary>
        /// cfg.yml's data_dir as the run saw it: absolute as written; relative, against the result folder's parent (where
        /// <c>--result_dir results/x</c> usually sits beside <c>data/</c>), then the working directory. Says which.
        /// </summary>
        public static (string Path, string How) ResolveDataDir(string folder, string dataDir)
        {
            if (string.IsNullOrWhiteSpace(dataDir))
                throw TrainedModel.Refuse(TrainerFolders.GsplatConfig + ": data_dir", "(missing)", "is not in cfg.yml, so gsplat's normalisation cannot be recomputed.",
                    "Pass the result folder simple_trainer.py wrote, or train again with --no-normalize-world-space.");
            if (Path.IsPathRooted(dataDir)) return (Path.GetFullPath(dataDir), "as written (absolute)");
            var parent = Path.GetDirectoryName(folder);
            var fromParent = Path.GetFullPath(Path.Combine(parent ?? folder, dataDir));
            if (Directory.Exists(fromParent)) return (fromParent, "resolved against the result folder's parent (" + fromParent + ")");
            var fromWorking = Path.GetFullPath(dataDir);
            if (Directory.Exists(fromWorking)) return (fromWorking, "resolved against the working directory (" + fromWorking + ")");
            throw TrainedModel.Refuse(TrainerFolders.GsplatConfig + ": data_dir", dataDir, "is neither " + fromParent + " (against the result folder's parent) nor " + fromWorking + " (against the working directory).",
                "Run place-splat from the folder simple_trainer.py ran in, or train again with --no-normalize-world-space.");
        }

        /// <summary>
        /// The four right-handed sign choices of the principal axes, each the whole transform T3·T2·T1; choices that end
        /// in the same transform (the upside-down turn undoes a y and z flip) are one candidate, named by both.
        /// </summary>
        public static List<(Matrix4x4d Transform, string Signs)> Candidates(ColmapSparseModel model)
        {
            var c2w = model.Poses.Select(CameraToWorldOpenCv).ToList();
            // colmap.py line 245: the points are float32 before they are transformed.
            var points = model.Points.Select(p => new Vector3d((float)p.X, (float)p.Y, (float)p.Z)).ToList();
            var t1 = SimilarityFromCameras(c2w);
            var p1 = points.Select(t1.MultiplyPoint).ToList();
            var (centroid, axes) = PrincipalAxes(p1);
            var result = new List<(Matrix4x4d, string)>();
            foreach (var signs in new[] { (1, 1, 1), (-1, -1, 1), (-1, 1, -1), (1, -1, -1) })
            {
                var v0 = axes[0] * signs.Item1; var v1 = axes[1] * signs.Item2; var v2 = axes[2] * signs.Item3;
                // rotation_matrix = eigenvectors.T: its rows are the axes; translation −R·centroid (normalize.py lines 105–110).
                var r = Matrix4x4d.FromRowMajor(v0.X, v0.Y, v0.Z, 0, v1.X, v1.Y, v1.Z, 0, v2.X, v2.Y, v2.Z, 0, 0, 0, 0, 1);
                var rc = r.MultiplyPoint(centroid);
                var t2 = Matrix4x4d.FromRowMajor(v0.X, v0.Y, v0.Z, -rc.X, v1.X, v1.Y, v1.Z, -rc.Y, v2.X, v2.Y, v2.Z, -rc.Z, 0, 0, 0, 1);
                var transform = t2 * t1;
                var z = p1.Select(p => t2.MultiplyPoint(p).Z).ToList();
                if (Median(z) > z.Average()) transform = Matrix4x4d.FromRowMajor(1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1) * transform; // T3, colmap.py 290–302
                var name = "(" + Sign(signs.Item1) + ", " + Sign(signs.Item2) + ", " + Sign(signs.Item3) + ")";
                // Two sign choices that differ in y and z end the same after the upside-down turn: one candidate.
                var same = result.FindIndex(r => Same(r.Item1, transform));
                if (same >= 0) result[same] = (result[same].Item1, result[same].Item2 + " = " + name);
                else result.Add((transform, name));
            }
            return result;
        }

        static bool Same(Matrix4x4d a, Matrix4x4d b)
        {
            var scale = Math.Abs(a.Determinant3x3) + 1e-300;
            for (var i = 0; i < 12; i++)
                if (Math.Abs(a[i / 4, i % 4] - b[i / 4, i % 4]) > 1e-9 * Math.Pow(scale, 1.0 / 3) * (1 + Math.Abs(a[i / 4, 3]))) return false;
            return true;
        }

        /// <summary>camtoworlds = inv(w2c) (colmap.py line 190): OpenCV axes, as gsplat keeps them.</summary>
        static Matrix4x4d CameraToWorldOpenCv(ColmapPose p)
        {
            var w2c = Matrix4x4d.FromRowMajor(p.R00, p.R01, p.R02, p.Translation.X, p.R10, p.R11, p.R12, p.Translation.Y, p.R20, p.R21, p.R22, p.Translation.Z, 0, 0, 0, 1);
            return AffineMaps.Inverse(w2c);
        }

        /// <summary>normalize.py lines 19–78 with center_method "focus" and strict_scaling False (the parser's call).</summary>
        public static Matrix4x4d SimilarityFromCameras(IReadOnlyList<Matrix4x4d> c2w)
        {
            // ups = R·(0, −1, 0) per camera; world_up their normalised mean.
            var up = Vector3d.Zero;
            foreach (var m in c2w) up += -m.Column(1);
            up = (up / c2w.Count).Normalized();
            var upCam = new Vector3d(0, -1, 0);
            var c = Vector3d.Dot(upCam, up);
            var cross = Vector3d.Cross(up, upCam);
            double[,] align;
            if (c > -1)
            {
                var skew = new double[3, 3] { { 0, -cross.Z, cross.Y }, { cross.Z, 0, -cross.X }, { -cross.Y, cross.X, 0 } };
                align = new double[3, 3];
                for (var i = 0; i < 3; i++)
                for (var j = 0; j < 3; j++)
                {
                    double sq = 0;
                    for (var k = 0; k < 3; k++) sq += skew[i, k] * skew[k, j];
                    align[i, j] = (i == j ? 1 : 0) + skew[i, j] + sq / (1 + c);
                }
            }
            else align = new double[3, 3] { { -1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
            var rAlign = Matrix4x4d.FromRowMajor(align[0, 0], align[0, 1], align[0, 2], 0, align[1, 0], align[1, 1], align[1, 2], 0, align[2, 0], align[2, 1], align[2, 2], 0, 0, 0, 0, 1);
            var t = c2w.Select(m => rAlign.MultiplyVector(m.Translation)).ToList();
            var fwds = c2w.Select(m => rAlign.MultiplyVector(m.Column(2))).ToList();
            var nearest = t.Select((ti, i) => ti + Vector3d.Dot(fwds[i], -ti) * fwds[i]).ToList();
            var translate = -new Vector3d(Median(nearest.Select(n => n.X)), Median(nearest.Select(n => n.Y)), Median(nearest.Select(n => n.Z)));
            var scale = 1 / Median(t.Select(ti => (ti + translate).Length));
            return AffineMaps.Scaled(Matrix4x4d.FromRowMajor(align[0, 0], align[0, 1], align[0, 2], translate.X, align[1, 0], align[1, 1], align[1, 2], translate.Y,
                align[2, 0], align[2, 1], align[2, 2], translate.Z, 0, 0, 0, 1), scale);
        }

        /// <summary>
        /// align_principal_axes' centroid (the component-wise median) and eigenvectors of np.cov (mean-centred, N − 1),
        /// largest eigenvalue first, the first flipped when the basis is left-handed (normalize.py lines 81–102).
        /// </summary>
        public static (Vector3d Centroid, Vector3d[] Axes) PrincipalAxes(IReadOnlyList<Vector3d> points)
        {
            var centroid = new Vector3d(Median(points.Select(p => p.X)), Median(points.Select(p => p.Y)), Median(points.Select(p => p.Z)));
            // np.cov of (points − centroid) subtracts the mean again, so the covariance is the points' own.
            var mean = Vector3d.Zero;
            foreach (var p in points) mean += p - centroid;
            mean /= points.Count;
            var cov = new double[3, 3];
            foreach (var p in points)
            {
                var d = p - centroid - mean;
                var v = new[] { d.X, d.Y, d.Z };
                for (var i = 0; i < 3; i++)
                for (var j = 0; j < 3; j++) cov[i, j] += v[i] * v[j];
            }
            for (var i = 0; i < 3; i++)
            for (var j = 0; j < 3; j++) cov[i, j] /= points.Count - 1;
            var (values, vectors) = SymmetricEigen.Solve(cov);
            var order = new[] { 0, 1, 2 }.OrderByDescending(i => values[i]).ToArray();
            var axes = order.Select(i => vectors[i]).ToArray();
            if (Vector3d.Dot(Vector3d.Cross(axes[0], axes[1]), axes[2]) < 0) axes[0] = -axes[0];
            return (centroid, axes);
        }

        /// <summary>The points' bounding-box diagonal: the scale of "equally good".</summary>
        static double Size(IReadOnlyList<Vector3d> points) => new Vector3d(points.Max(p => p.X) - points.Min(p => p.X), points.Max(p => p.Y) - points.Min(p => p.Y), points.Max(p => p.Z) - points.Min(p => p.Z)).Length;

        /// <summary>The median and mean distance from the PLY's centres (up to 20 000, evenly picked) to the nearest transformed COLMAP point.</summary>
        static (double Median, double Mean) Match(Matrix4x4d transform, IReadOnlyList<Vector3d> points, IReadOnlyList<Vector3d> centres)
        {
            var xyz = new float[points.Count * 3];
            for (var i = 0; i < points.Count; i++)
            {
                var p = transform.MultiplyPoint(points[i]);
                xyz[3 * i] = (float)p.X; xyz[3 * i + 1] = (float)p.Y; xyz[3 * i + 2] = (float)p.Z;
            }
            var tree = new PointKdTree(xyz);
            var step = Math.Max(1, centres.Count / 20000);
            var distances = new List<double>();
            for (var i = 0; i < centres.Count; i += step) distances.Add(Math.Sqrt(tree.NearestDistanceSquared(centres[i].X, centres[i].Y, centres[i].Z)));
            return distances.Count == 0 ? (double.PositiveInfinity, double.PositiveInfinity) : (Median(distances), distances.Average());
        }

        /// <summary>np.median: the middle value, or the mean of the two middle values.</summary>
        public static double Median(IEnumerable<double> values)
        {
            var sorted = values.OrderBy(v => v).ToArray();
            var n = sorted.Length;
            return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
        }

        static string Sign(int s) => s > 0 ? "+" : "−";

        static string Show(double d) => d == 0 ? "0" : d.ToString("0.####e0", CultureInfo.InvariantCulture);
    }
}
