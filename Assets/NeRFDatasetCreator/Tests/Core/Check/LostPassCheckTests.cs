using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Issue 32 item 2: the self-check never says OK on a dataset with a lost pass. A frame key naming a missing file or
    /// one outside the dataset, and a recorded geometry pack that is missing, truncated or replaced, each fail the check
    /// with a problem naming the file and the fix (before, each was skipped and the check exited OK).
    /// </summary>
    [TestFixture]
    public class LostPassCheckTests
    {
        TempFolder _temp;
        string _clean, _steps;
        int _copies;

        [OneTimeSetUp]
        public void Render()
        {
            _temp = new TempFolder();
            _clean = AnalyticDataset.Write(_temp.Path, "clean", new AnalyticDataset.Options { Train = 4, Val = 1, Test = 1, PointCloud = 0 });
            _steps = AnalyticDataset.Write(_temp.Path, "steps", new AnalyticDataset.Options
            {
                Width = 160, Height = 120, Supersampling = 1, Train = 4, Val = 1, Test = 2, TimeSteps = 3, PointCloud = 0,
                MeshesAt = AnalyticSceneMeshes.At, GeometryPackEveryStep = true,
            });
        }

        [OneTimeTearDown] public void Delete() => _temp.Dispose();

        string Copy(string source) => DatasetFaults.Copy(source, _temp.Combine("lost-" + ++_copies));

        static DatasetCheckReport Check(string folder)
        {
            var report = DatasetCheck.Run(folder, new DatasetCheckOptions());
            TestContext.WriteLine(string.Join("\n", report.SummaryLines) + "\n" + string.Join("\n", report.Problems.Take(12)));
            return report;
        }

        static JObject Frame0(string folder, string split, out string path)
        {
            path = Path.Combine(folder, DatasetLayout.TransformsFileName(split));
            return (JObject)JObject.Parse(File.ReadAllText(path))["frames"][0];
        }

        static void SetKey(string folder, string split, string key, string value)
        {
            var path = Path.Combine(folder, DatasetLayout.TransformsFileName(split));
            var json = JObject.Parse(File.ReadAllText(path));
            json["frames"][0][key] = value;
            File.WriteAllText(path, json.ToString());
        }

        [Test]
        public void TheCleanDatasetsPass()
        {
            Assert.That(Check(_clean).Failed, Is.False, "the clean copy passes, so each failure below is the planted fault's");
            Assert.That(Check(_steps).Failed, Is.False);
        }

        [Test]
        public void ADepthPathNamingAMissingFileFails()
        {
            var folder = Copy(_clean);
            var depth = (string)Frame0(folder, "train", out _)["depth_path"];
            Assert.That(depth, Is.Not.Null, "the analytic dataset writes depth_path");
            File.Delete(Path.Combine(folder, ExportPaths.Normalise(depth)));

            var report = Check(folder);
            Assert.That(report.Failed, Is.True);
            var problem = report.Problems.Single(p => p.Check == CheckDatasetReader.CheckName && p.Message.Contains("depth"));
            Assert.That(problem.Frame, Is.EqualTo(0));
            Assert.That(problem.Message, Does.StartWith("depth_path " + depth + " is missing. Restore the file, or capture the dataset again"));
        }

        [Test]
        public void ASharpPathOutsideTheDatasetFails()
        {
            var folder = Copy(_clean);
            var outside = _temp.Combine("outside-" + _copies + ".png");
            File.Copy(Path.Combine(folder, "train", "r_0.png"), outside);
            SetKey(folder, "train", "sharp_path", "../" + Path.GetFileName(outside));

            var report = Check(folder);
            Assert.That(report.Failed, Is.True);
            var problem = report.Problems.Single(p => p.Check == CheckDatasetReader.CheckName);
            Assert.That(problem.Message, Does.StartWith("sharp_path ../" + Path.GetFileName(outside) + " leaves the dataset folder ("));
            Assert.That(problem.Message, Does.EndWith("Copy the file into the dataset folder and name it relative to it, or capture the dataset again."));
        }

        static GeometryPackEntry Entry(string folder, int step) =>
            GeometryPackStepRecord.Entries(JObject.Parse(File.ReadAllText(Path.Combine(folder, DatasetLayout.ConfigFileName)))).Single(e => e.Step == step);

        static void AssertPackFailure(DatasetCheckReport report, string file, string why)
        {
            Assert.That(report.Failed, Is.True);
            Assert.That(report.Results.Single(r => r.Name == GeometryPackDepthCheck.CheckName).Status, Is.EqualTo(DatasetCheckStatus.Failed));
            var problem = report.Problems.Single(p => p.Check == GeometryPackDepthCheck.CheckName);
            Assert.That(problem.File, Is.EqualTo(file));
            Assert.That(problem.Message, Does.StartWith("is recorded in dataset_config.json as the geometry pack of time step 1 but " + why));
            Assert.That(problem.Message, Does.EndWith("Capture the dataset again with the geometry pack on (or remove the geometry record from dataset_config.json if the dataset should have none)."));
        }

        [Test]
        public void ATruncatedGeometryPackFails()
        {
            var folder = Copy(_steps);
            var file = Entry(folder, 1).File;
            var path = Path.Combine(folder, file);
            var bytes = File.ReadAllBytes(path);
            File.WriteAllBytes(path, bytes.Take(bytes.Length / 2).ToArray());
            AssertPackFailure(Check(folder), file, "does not have the SHA-256 recorded for it");
        }

        [Test]
        public void AForeignGeometryPackWithoutARecordedHashFailsAsUnreadable()
        {
            var folder = Copy(_steps);
            var file = Entry(folder, 1).File;
            // An older record without sha256: the mesh itself must still be readable.
            var configPath = Path.Combine(folder, DatasetLayout.ConfigFileName);
            var config = JObject.Parse(File.ReadAllText(configPath));
            foreach (var token in config.SelectTokens("$..sha256").ToList()) token.Parent.Remove();
            File.WriteAllText(configPath, config.ToString());
            File.WriteAllText(Path.Combine(folder, file), "solid foreign\nendsolid foreign\n");
            AssertPackFailure(Check(folder), file, "cannot be read: ");
        }

        [Test]
        public void AMissingGeometryPackFails()
        {
            var folder = Copy(_steps);
            var file = Entry(folder, 1).File;
            File.Delete(Path.Combine(folder, file));
            AssertPackFailure(Check(folder), file, "does not exist.");
        }
    }
}
