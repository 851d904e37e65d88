using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// 3DGS, trained on a Blender folder without points3d.ply, writes its random cloud there under that very name
    /// (graphdeco-inria/gaussian-splatting scene/dataset_readers.py, readNerfSyntheticInfo: 100 000 points,
    /// <c>np.random.random((num_pts, 3)) * 2.6 - 1.3</c>, stored with storePly). Such a file must never become the
    /// target's surface in an export: only the cloud recorded with its SHA-256 in dataset_config.json is ours.
    /// </summary>
    public class PointCloudOwnershipTests
    {
        LegoDataset _lego;

        [SetUp]
        public void SetUp() => _lego = new LegoDataset();

        [TearDown]
        public void TearDown() => _lego.Dispose();

        string PlyPath => Path.Combine(_lego.Root, "points3d.ply");

        /// <summary>A storePly file as 3DGS writes it with plyfile: no comment, binary little-endian, 27 bytes a vertex.</summary>
        void Write3dgsRandomCloud(int count)
        {
            var header = "ply\nformat binary_little_endian 1.0\nelement vertex " + count + "\n" +
                         "property float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\n" +
                         "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
            using (var file = File.Create(PlyPath))
            using (var w = new BinaryWriter(file))
            {
                w.Write(Encoding.ASCII.GetBytes(header));
                var random = new System.Random(1);
                for (var i = 0; i < count; i++)
                {
                    for (var k = 0; k < 3; k++) w.Write((float)(random.NextDouble() * 2.6 - 1.3));
                    for (var k = 0; k < 3; k++) w.Write(0f);
                    w.Write((byte)128); w.Write((byte)128); w.Write((byte)128);
                }
            }
        }

        IReadOnlyList<CloudPoint> WriteOwnCloud(bool record)
        {
            var cloud = RandomInitCloud.Cube(50, 0.5, 7);
            PlyWriter.Write(PlyPath, cloud);
            var config = new JObject { ["generator"] = PluginInfo.Name };
            if (record) config[PointCloudRecord.Key] = PointCloudRecord.Of(PlyPath, "points3d.ply", cloud.Count).ToJson();
            File.WriteAllText(Path.Combine(_lego.Root, DatasetLayout.ConfigFileName), config.ToString());
            return cloud;
        }

        [Test]
        public void Sha256_MatchesTheStandardTestVector()
        {
            // FIPS 180-2, appendix B.1: SHA-256("abc").
            var path = Path.Combine(_lego.Root, "abc.bin");
            File.WriteAllBytes(path, Encoding.ASCII.GetBytes("abc"));
            Assert.That(PointCloudRecord.HashOf(path), Is.EqualTo("ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"));
        }

        [Test]
        public void ARecordedCloudIsTheTargetsSurface()
        {
            WriteOwnCloud(record: true);
            var warnings = new List<ValidationProblem>();
            Assert.That(PointCloudOwnership.IsOwn(_lego.Root, warnings), Is.True);
            Assert.That(warnings, Is.Empty);
            var ns = JObject.Parse(File.ReadAllText(DatasetConverter.Convert(_lego.Root, ExportTarget.Nerfstudio).MainFile));
            Assert.That((string)ns["ply_file_path"], Is.EqualTo("points3d.ply"));
        }

        [Test]
        public void The3dgsRandomCloud_IsForeign_InConvertAndValidate()
        {
            Write3dgsRandomCloud(1000);

            var ns = DatasetConverter.Convert(_lego.Root, ExportTarget.Nerfstudio);
            Assert.That(JObject.Parse(File.ReadAllText(ns.MainFile))["ply_file_path"], Is.Null, "never the target's surface");
            Assert.That(ns.Warnings.Single(w => w.Field == "points3d.ply").Reason, Does.Contain("not written by this plugin").And.Contain("NOT used"));

            var colmap = DatasetConverter.Convert(_lego.Root, ExportTarget.Colmap);
            var sparse = Path.Combine(colmap.OutputDirectory, "sparse", "0");
            Assert.That(File.Exists(Path.Combine(sparse, "points3D.ply")), Is.False, "not copied");
            Assert.That(colmap.Warnings.Select(w => w.Field), Does.Contain("points3D.txt"), "the random-points warning is back");
            Assert.That(colmap.Warnings.Select(w => w.Field), Does.Contain("points3d.ply"));

            var report = DatasetValidator.Validate(_lego.Root);
            Assert.That(report.Warnings.Select(w => w.File), Does.Contain("points3d.ply"));
        }

        [Test]
        public void OurCloudWithoutItsRecord_IsForeign()
        {
            WriteOwnCloud(record: false);
            var warnings = new List<ValidationProblem>();
            Assert.That(PointCloudOwnership.IsOwn(_lego.Root, warnings), Is.False);
            Assert.That(warnings.Single().Reason, Does.Contain("holds no record"));
        }

        [Test]
        public void AChangedCloud_IsForeign()
        {
            WriteOwnCloud(record: true);
            var bytes = File.ReadAllBytes(PlyPath);
            bytes[bytes.Length - 1] ^= 1; // one colour bit
            File.WriteAllBytes(PlyPath, bytes);

            var warnings = new List<ValidationProblem>();
            Assert.That(PointCloudOwnership.IsOwn(_lego.Root, warnings), Is.False);
            Assert.That(warnings.Single().Reason, Does.Contain("SHA-256"));
        }

        [Test]
        public void ARecordedCloudThatIsMissing_IsAWarning()
        {
            WriteOwnCloud(record: true);
            File.Delete(PlyPath);
            var warnings = new List<ValidationProblem>();
            Assert.That(PointCloudOwnership.IsOwn(_lego.Root, warnings), Is.False);
            Assert.That(warnings.Single().Value, Is.EqualTo("missing"));
        }

        [Test]
        public void PlyReader_ReadsOurFileAnd3dgsFileAlike()
        {
            Write3dgsRandomCloud(3);
            Assert.That(PlyReader.Read(PlyPath), Has.Count.EqualTo(3), "comments are not part of the layout");
        }
    }
}
