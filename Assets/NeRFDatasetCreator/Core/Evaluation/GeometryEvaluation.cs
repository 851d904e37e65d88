using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>What <see cref="GeometryEvaluation.Run"/> measured and how.</summary>
    public sealed class GeometryResult
    {
        public string ReconstructionPath { get; internal set; }

        /// <summary>"mesh (n triangles, sampled to m points)" or "point cloud (n points)".</summary>
        public string ReconstructionKind { get; internal set; }

        public string TruthPath { get; internal set; }
        public string TruthSource { get; internal set; }
        public int TruthTriangles { get; internal set; }
        public double TruthDiagonal { get; internal set; }
        public string ThresholdRule { get; internal set; }
        public string ObservedRule { get; internal set; }
        public int TrainViewsUsed { get; internal set; }

        /// <summary>The time step compared (a dynamic dataset), or null.</summary>
        public int? Step { get; internal set; }

        /// <summary>That step's normalised time, when known.</summary>
        public double? Time { get; internal set; }
        public SurfaceDistances Distances { get; internal set; }
    }

    /// <summary>
    /// <c>--geometry</c>: the reconstruction against the ground-truth mesh. The mesh comes from <c>--gt-mesh</c>, else the
    /// geometry pack (<c>dataset_config.json</c>'s <c>geometry.file</c>, else <c>geometry/target_mesh.ply</c>); it is
    /// sampled area-uniformly (<see cref="SurfaceSampler"/>, fixed seed) into <see cref="DefaultTruthPoints"/> points; the
    /// points the train split's depth maps saw are kept for completeness and recall (<see cref="ObservedPoints"/>, tolerance
    /// = the threshold); a reconstruction mesh is sampled at the same density, a point cloud used as it is, a trained
    /// Gaussian splat's PLY as its opaque centres in the output frame (<see cref="TrainedSplatCentres"/>).
    /// </summary>
    public static class GeometryEvaluation
    {
        public const int DefaultTruthPoints = 1_000_000;

        /// <summary>The default threshold: this fraction of the ground-truth mesh's bounding-box diagonal.</summary>
        public const double DefaultThresholdFraction = 0.005;

        public const long TruthSeed = 0x6e657266; // fixed: the same dataset and mesh give the same points every run
        public const long ReconstructionSeed = 0x72656366;

        /// <param name="step">A dynamic dataset's time step (<c>--step</c>); <see cref="GeometryTruth.Resolve"/> says when it is needed.</param>
        public static GeometryResult Run(EvaluationDataset dataset, string reconstructionPath, string truthMeshPath, double? threshold, int truthPoints, Action<string> progress, int? step = null) =>
            Run(GeometryTruth.Resolve(dataset, reconstructionPath, truthMeshPath, step), reconstructionPath, threshold, truthPoints, progress);

        public static GeometryResult Run(GeometryTruth truthChoice, string reconstructionPath, double? threshold, int truthPoints, Action<string> progress)
        {
            var result = new GeometryResult { ReconstructionPath = Path.GetFullPath(reconstructionPath), Step = truthChoice.Step, Time = truthChoice.Time };
            var truthPath = truthChoice.Path;
            result.TruthPath = truthPath;
            result.TruthSource = truthChoice.Source;
            var truthMesh = GeometryFile.Read(truthPath, GeometryFile.Truth);
            if (truthMesh.TriangleCount == 0)
                throw new InvalidParameterException(new[] { new ValidationProblem(GeometryFile.Truth, truthPath, "has no faces; the ground truth must be a surface to sample.", "Pass the target's triangle mesh.") });
            result.TruthTriangles = truthMesh.TriangleCount;
            var truthArea = Area(truthMesh);
            // Checked here, not left to the sampler, whose message is the capture's point-cloud setting (pointCloud.meshes).
            if (!(truthArea > 0) || double.IsInfinity(truthArea))
                throw new InvalidParameterException(new[] { new ValidationProblem(GeometryFile.Truth, truthPath, "has " + truthMesh.TriangleCount + " triangle(s) but " + (truthArea > 0 ? "an infinite" : "no") + " surface area (every face degenerate); the ground truth must be a surface to sample.", "Pass the target's triangle mesh.") });
            progress?.Invoke("geometry: sampling " + truthPoints + " points on the ground-truth mesh (" + truthMesh.TriangleCount + " triangles)");
            var truth = ToFloats(SurfaceSampler.Sample(new[] { truthMesh }, truthPoints, TruthSeed));
            result.TruthDiagonal = Diagonal(truthMesh.Vertices);
            double tau;
            if (threshold.HasValue)
            {
                tau = threshold.Value;
                result.ThresholdRule = "given with --threshold, output units";
            }
            else
            {
                tau = DefaultThresholdFraction * result.TruthDiagonal;
                result.ThresholdRule = DefaultThresholdFraction.ToString("0.###", System.Globalization.CultureInfo.InvariantCulture) + " × the ground-truth mesh's bounding-box diagonal (" +
                                       result.TruthDiagonal.ToString("0.####", System.Globalization.CultureInfo.InvariantCulture) + " output units)";
            }

            var observed = new bool[truth.Length / 3];
            var train = truthChoice.Train;
            var frames = truthChoice.TrainFrames;
            if (truthChoice.TrainHasDepth)
            {
                var which = truthChoice.Step.HasValue ? " train views of time step " + truthChoice.Step.Value : " train views";
                progress?.Invoke("geometry: keeping the ground truth the " + frames.Count + which + "' depth maps saw");
                foreach (var frame in frames)
                {
                    var png = PngReader.Read(frame.DepthPath);
                    var depth = EvaluationImages.DepthPng(png, train.DepthScale, frame.DepthPath);
                    var focal = train.Focal(png.Width);
                    ObservedPoints.Mark(truth, observed, frame.CameraToWorld, depth, png.Width, png.Height, focal, train.Cx ?? png.Width / 2.0, train.Cy ?? png.Height / 2.0, tau);
                }
                result.TrainViewsUsed = frames.Count;
                result.ObservedRule = "a ground-truth point counts for completeness and recall when at least one of the " + frames.Count + which +
                                      " sees it: it projects inside the image in front of the camera and that pixel's ground-truth depth is within the threshold + " + ObservedPoints.DefaultPixelSlack.ToString(System.Globalization.CultureInfo.InvariantCulture) + " pixel footprints of the point's depth";
            }
            else
            {
                for (var i = 0; i < observed.Length; i++) observed[i] = true;
                result.ObservedRule = "the train" + (truthChoice.Step.HasValue ? " views of time step " + truthChoice.Step.Value + " have" : " split has") + " no depth maps, so every ground-truth point counts (none could be ruled unobserved)";
            }

            float[] reconstruction;
            if (GaussianPly.IsGaussianSplat(reconstructionPath))
            {
                // A trained splat (issue 34): its opaque centres, moved out of the trainer's frame as place-splat moves them.
                var splat = TrainedSplatCentres.Read(reconstructionPath);
                reconstruction = new float[splat.Centres.Count * 3];
                for (var i = 0; i < splat.Centres.Count; i++)
                {
                    reconstruction[3 * i] = (float)splat.Centres[i].X;
                    reconstruction[3 * i + 1] = (float)splat.Centres[i].Y;
                    reconstruction[3 * i + 2] = (float)splat.Centres[i].Z;
                }
                result.ReconstructionKind = splat.Kind;
                if (splat.Centres.Count == 0)
                    throw new InvalidParameterException(new[] { new ValidationProblem(GeometryFile.Reconstruction, reconstructionPath, "has no Gaussian with opacity above " + TrainedSplatCentres.OpacityThreshold.ToString(System.Globalization.CultureInfo.InvariantCulture) + ", so there is no surface to score.", "Pass the PLY of a trained model (a later iteration).") });
                progress?.Invoke("geometry: nearest neighbours both ways");
                result.Distances = SurfaceDistances.Compute(reconstruction, truth, observed, tau);
                return result;
            }
            var reconstructionMesh = GeometryFile.Read(reconstructionPath);
            if (reconstructionMesh.TriangleCount > 0)
            {
                var reconstructionArea = Area(reconstructionMesh);
                if (!(reconstructionArea > 0) || double.IsInfinity(reconstructionArea))
                    throw new InvalidParameterException(new[] { new ValidationProblem(GeometryFile.Reconstruction, reconstructionPath, "has " + reconstructionMesh.TriangleCount + " triangle(s) but " + (reconstructionArea > 0 ? "an infinite" : "no") + " surface area (every face degenerate), so it has no surface to sample.", "Export the reconstruction's mesh again, or its points without faces.") });
                var count = (int)Math.Max(1000, Math.Min(SurfaceSampler.MaxCount, Math.Round(truthPoints * reconstructionArea / truthArea)));
                progress?.Invoke("geometry: sampling " + count + " points on the reconstruction mesh (" + reconstructionMesh.TriangleCount + " triangles)");
                reconstruction = ToFloats(SurfaceSampler.Sample(new[] { reconstructionMesh }, count, ReconstructionSeed));
                result.ReconstructionKind = "mesh (" + reconstructionMesh.TriangleCount + " triangles), sampled to " + count + " points at the ground truth's density";
            }
            else
            {
                reconstruction = new float[reconstructionMesh.Vertices.Count * 3];
                for (var i = 0; i < reconstructionMesh.Vertices.Count; i++)
                {
                    reconstruction[3 * i] = (float)reconstructionMesh.Vertices[i].X;
                    reconstruction[3 * i + 1] = (float)reconstructionMesh.Vertices[i].Y;
                    reconstruction[3 * i + 2] = (float)reconstructionMesh.Vertices[i].Z;
                }
                result.ReconstructionKind = "point cloud (" + reconstructionMesh.Vertices.Count + " points)";
            }
            progress?.Invoke("geometry: nearest neighbours both ways");
            result.Distances = SurfaceDistances.Compute(reconstruction, truth, observed, tau);
            return result;
        }

        /// <summary>The ground-truth mesh's path and where it came from; refuses (naming --gt-mesh or --step) when there is none or the step is ambiguous.</summary>
        public static string TruthPath(EvaluationDataset dataset, string reconstructionPath, string truthMeshPath, out string source, int? step = null)
        {
            var truth = GeometryTruth.Resolve(dataset, reconstructionPath, truthMeshPath, step);
            source = truth.Source;
            return truth.Path;
        }

        public static double Area(SurfaceMesh mesh)
        {
            double sum = 0;
            for (var t = 0; t < mesh.TriangleCount; t++) sum += mesh.TriangleArea(t);
            return sum;
        }

        static double Diagonal(IReadOnlyList<Vector3d> vertices)
        {
            var min = new Vector3d(vertices.Min(v => v.X), vertices.Min(v => v.Y), vertices.Min(v => v.Z));
            var max = new Vector3d(vertices.Max(v => v.X), vertices.Max(v => v.Y), vertices.Max(v => v.Z));
            return (max - min).Length;
        }

        public static float[] ToFloats(IReadOnlyList<CloudPoint> points)
        {
            var result = new float[points.Count * 3];
            for (var i = 0; i < points.Count; i++)
            {
                result[3 * i] = (float)points[i].Position.X;
                result[3 * i + 1] = (float)points[i].Position.Y;
                result[3 * i + 2] = (float)points[i].Position.Z;
            }
            return result;
        }
    }
}
