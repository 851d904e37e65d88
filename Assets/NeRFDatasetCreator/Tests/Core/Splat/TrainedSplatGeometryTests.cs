using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// <c>evaluate --geometry &lt;trained PLY&gt;</c>: a splat's opaque centres, in the trainer's frame, are scored against
    /// the ground-truth mesh in the output frame through the same map place-splat composes; faint Gaussians are left
    /// out; a splat outside any trainer's folder is refused because its frame is unknown.
    /// </summary>
    [TestFixture]
    public class TrainedSplatGeometryTests
    {
        TempFolder _temp;

        [SetUp] public void Create() => _temp = new TempFolder();

        [TearDown] public void Delete() => _temp.Dispose();

        /// <summary>The fixture mesh in the output frame, as an OBJ: the ground truth.</summary>
        string TruthObj()
        {
            var path = _temp.Combine("truth.obj");
            var text = new StringBuilder();
            foreach (var v in SplatFixtures.MeshUnity.Select(SplatFixtures.Normalisation.ApplyToUnityPoint))
                text.Append("v " + v.X.ToString("R", CultureInfo.InvariantCulture) + " " + v.Y.ToString("R", CultureInfo.InvariantCulture) + " " + v.Z.ToString("R", CultureInfo.InvariantCulture) + "\n");
            for (var t = 0; t < SplatFixtures.Triangles.Length; t += 3)
                text.Append("f " + (SplatFixtures.Triangles[t] + 1) + " " + (SplatFixtures.Triangles[t + 1] + 1) + " " + (SplatFixtures.Triangles[t + 2] + 1) + "\n");
            File.WriteAllText(path, text.ToString());
            return path;
        }

        GeometryResult Score(string ply)
        {
            var dataset = SplatFixtures.WriteDataset(_temp.Combine("dataset"));
            // evaluate reads the split's images for their size: blank ones of the fixture's size.
            for (var i = 0; i < 8; i++) TestPng.Write(Path.Combine(dataset, "train", "r_" + i + ".png"), SplatFixtures.Width, SplatFixtures.Height);
            return GeometryEvaluation.Run(EvaluationDataset.Read(dataset, "train"), ply, TruthObj(), 0.01, 20000, null);
        }

        /// <summary>The sampled points in the output frame as an ordinary point cloud (no opacity), scored the old way.</summary>
        GeometryResult PlainCloudScore()
        {
            var path = _temp.Combine("plain", "points.ply");
            Directory.CreateDirectory(Path.GetDirectoryName(path));
            PlyWriter.Write(path, SplatFixtures.SampleOutput().Select(p => new CloudPoint(p, Vector3d.UnitZ, 0, 0, 0)).ToList());
            var result = Score(path);
            Assert.That(result.ReconstructionKind, Is.EqualTo("point cloud (600 points)"));
            return result;
        }

        /// <summary>The splat's centres in the nerfstudio frame plus 50 faint floaters (opacity sigmoid(−3) ≈ 0.05) far off.</summary>
        string NerfstudioRunWithFloaters()
        {
            var run = _temp.Combine("run");
            SplatFixtures.NerfstudioRun(run, new Vector3d[0], exportFolder: null);
            var centres = SplatFixtures.SampleOutput().Select(SplatFixtures.ToNerfstudio).ToList();
            var logits = centres.Select(_ => 2.0).ToList();
            for (var i = 0; i < 50; i++) { centres.Add(new Vector3d(5 + i * 0.01, 5, 5)); logits.Add(-3); }
            var ply = Path.Combine(run, "exports", "splat.ply");
            SplatFixtures.WriteGaussianPly(ply, centres, logits);
            return ply;
        }

        [Test]
        public void ANerfstudioSplatIsScoredInTheOutputFrame()
        {
            var result = Score(NerfstudioRunWithFloaters());
            // The same score as the centres written in the output frame as a plain point cloud: the map is undone exactly
            // (float32 storage aside) and the faint floaters are out; in nerfstudio's own frame the centres are far off.
            var plain = PlainCloudScore();
            Assert.That(result.Distances.Accuracy, Is.EqualTo(plain.Distances.Accuracy).Within(1e-6));
            Assert.That(result.Distances.Completeness, Is.EqualTo(plain.Distances.Completeness).Within(1e-6));
            Assert.That(result.Distances.Precision, Is.EqualTo(plain.Distances.Precision), "the 50 faint floaters would lower it to 600/650 of this");
            Assert.That(result.ReconstructionKind, Does.StartWith("Gaussian splat (600 of 650 centres with opacity > 0.5, from nerfstudio"));
        }

        [Test]
        public void AThreeDgsSplatIsScoredAsItIs()
        {
            var model = SplatFixtures.GaussianSplattingModel(_temp.Combine("model"), SplatFixtures.SampleOutput());
            var result = Score(Path.Combine(model, "point_cloud", "iteration_30000", "point_cloud.ply"));
            Assert.That(result.Distances.Accuracy, Is.EqualTo(PlainCloudScore().Distances.Accuracy).Within(1e-6));
            Assert.That(result.ReconstructionKind, Does.Contain("from 3dgs"));
        }

        [Test]
        public void ASplatOutsideAnyTrainersFolderIsRefused()
        {
            var loose = _temp.Combine("loose", "splat.ply");
            SplatFixtures.WriteGaussianPly(loose, SplatFixtures.SampleOutput());
            var e = Assert.Throws<InvalidParameterException>(() => Score(loose));
            Assert.That(e.Problems.Single().Field, Is.EqualTo("--geometry"));
            Assert.That(e.Problems.Single().Reason, Does.Contain("is a Gaussian splat, but no trainer's output folder holds it"));
        }
    }
}
