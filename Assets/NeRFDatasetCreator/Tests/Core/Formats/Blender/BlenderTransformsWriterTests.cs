using System;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class BlenderTransformsWriterTests
    {
        static CapturePlan SmallPlan() =>
            CapturePlan.Build(DatasetSettingsJson.Read(Fixtures.Text("golden", "small_dataset_settings.json")).Settings, PlanTarget.AtOrigin);

        [TestCase(DatasetSplit.Train)]
        [TestCase(DatasetSplit.Val)]
        [TestCase(DatasetSplit.Test)]
        public void WritesExactlyTheGoldenFiles(DatasetSplit split)
        {
            var expected = Fixtures.Text("golden", "small_dataset", DatasetLayout.TransformsFileName(split)).Replace("\r\n", "\n");
            Assert.That(BlenderTransformsWriter.Write(SmallPlan(), split), Is.EqualTo(expected));
        }

        [Test]
        public void KeyOrderIsNerfSyntheticsWithTheExtraKeysAfterCameraAngleX()
        {
            var lego = JObject.Parse(Fixtures.Text("nerf_synthetic_lego", "transforms_train.json"));
            var ours = JObject.Parse(BlenderTransformsWriter.Write(SmallPlan(), DatasetSplit.Train));
            var ourKeys = ours.Properties().Select(p => p.Name).ToList();
            // nerf_synthetic: camera_angle_x first, frames last.
            Assert.That(lego.Properties().Select(p => p.Name), Is.EqualTo(new[] { "camera_angle_x", "frames" }));
            Assert.That(ourKeys.First(), Is.EqualTo("camera_angle_x"));
            Assert.That(ourKeys.Last(), Is.EqualTo("frames"));
            Assert.That(ourKeys, Is.EqualTo(new[]
            {
                "camera_angle_x", "camera_angle_y", "fl_x", "fl_y", "cx", "cy", "w", "h", "aabb_scale", "integer_depth_scale", "depth_unit_scale_factor", "scene_normalisation", "frames",
            }));
            var legoFrameKeys = ((JObject)lego["frames"][0]).Properties().Select(p => p.Name).ToList();
            var ourFrameKeys = ((JObject)ours["frames"][0]).Properties().Select(p => p.Name).ToList();
            Assert.That(ourFrameKeys.Take(3), Is.EqualTo(legoFrameKeys));
            Assert.That(ourFrameKeys.Skip(3), Is.EqualTo(new[] { "depth_path", "depth_file_path", "mask_path" }));
        }

        [Test]
        public void IntrinsicsFollowTheHorizontalFieldOfView()
        {
            // 60° vertical at 400×300: f = 150 / tan 30°; horizontal = 2·atan(tan 30° · 4/3) (not the vertical 60°).
            var doc = JObject.Parse(BlenderTransformsWriter.Write(SmallPlan(), DatasetSplit.Train));
            var f = 150 / Math.Tan(Math.PI / 6);
            Assert.That((double)doc["camera_angle_x"], Is.EqualTo(2 * Math.Atan(Math.Tan(Math.PI / 6) * 4 / 3)).Within(1e-15));
            Assert.That((double)doc["camera_angle_y"], Is.EqualTo(Math.PI / 3).Within(1e-15));
            Assert.That((double)doc["fl_x"], Is.EqualTo(f).Within(1e-12));
            Assert.That((double)doc["fl_y"], Is.EqualTo(f).Within(1e-12));
            Assert.That((double)doc["cx"], Is.EqualTo(200.0));
            Assert.That((double)doc["cy"], Is.EqualTo(150.0));
            Assert.That((int)doc["w"], Is.EqualTo(400));
            Assert.That((int)doc["h"], Is.EqualTo(300));
            Assert.That((int)doc["aabb_scale"], Is.EqualTo(1));
            // NeRF's loader derives its focal from camera_angle_x and the image width: it must agree with fl_x.
            Assert.That(0.5 * 400 / Math.Tan(0.5 * (double)doc["camera_angle_x"]), Is.EqualTo(f).Within(1e-9));
        }

        [Test]
        public void HaloCameraZeroSitsWhereTheGeometrySays()
        {
            // Halo at 30° elevation, azimuth 0, distance 4: (4 cos 30°, 0, 4 sin 30°) in the Z-up output world,
            // looking back at the origin.
            var doc = JObject.Parse(BlenderTransformsWriter.Write(SmallPlan(), DatasetSplit.Train));
            var m = doc["frames"][0]["transform_matrix"];
            Assert.That((double)m[0][3], Is.EqualTo(4 * Math.Cos(Math.PI / 6)).Within(1e-12));
            Assert.That((double)m[1][3], Is.EqualTo(0.0).Within(1e-12));
            Assert.That((double)m[2][3], Is.EqualTo(2.0).Within(1e-12));
            Assert.That((double)m[0][2], Is.EqualTo(Math.Cos(Math.PI / 6)).Within(1e-12), "camera +Z points away from the target");
            Assert.That((double)m[2][2], Is.EqualTo(0.5).Within(1e-12));
        }

        [Test]
        public void ExtraKeysOnlyForFilesThatAreWritten()
        {
            var plan = SmallPlan();
            var train = JObject.Parse(BlenderTransformsWriter.Write(plan, DatasetSplit.Train));
            var test = JObject.Parse(BlenderTransformsWriter.Write(plan, DatasetSplit.Test));
            Assert.That((string)train["frames"][1]["depth_path"], Is.EqualTo("./train/r_1_depth_0000.png"));
            Assert.That((string)train["frames"][1]["depth_file_path"], Is.EqualTo("./train/r_1_depth_0000.png"));
            Assert.That((string)train["frames"][1]["mask_path"], Is.EqualTo("./train/r_1_mask_0000.png"));
            Assert.That(train["frames"][1]["normal_path"], Is.Null);
            Assert.That((double)train["integer_depth_scale"], Is.EqualTo(0.001));
            Assert.That((double)train["depth_unit_scale_factor"], Is.EqualTo(0.001));
            // The test split writes normals (PNG and EXR) but no depth: no depth keys at all.
            Assert.That(test["integer_depth_scale"], Is.Null);
            Assert.That(test["depth_unit_scale_factor"], Is.Null);
            Assert.That(test["frames"][0]["depth_path"], Is.Null);
            Assert.That((string)test["frames"][0]["normal_path"], Is.EqualTo("./test/r_0_normal_0000.png"));
        }

        [Test]
        public void FramesAreTheTextNewtonsoftWritesForTheSameTree()
        {
            // The frames are written by hand (TransformsFramesText); the reference is Newtonsoft's indented writer on
            // the same JSON tree, every key kind included: time keys of a multi-view capture, depth, normal and mask paths.
            var settings = new DatasetSettings { Seed = 5, Width = 16, Height = 16 };
            settings.Train.Count = 3;
            settings.Train.Depth = ExtraOutput.PngAndExr;
            settings.Train.Normal = ExtraOutput.PngAndExr;
            settings.Train.Mask = true;
            settings.Val.Count = 2;
            settings.Test.Count = 1;
            settings.Time.Mode = TimeMode.MultiView;
            settings.Time.StartSeconds = 2;
            settings.Time.EndSeconds = 6;
            settings.Time.Steps = 3;
            var plans = new[] { CapturePlan.Build(settings, PlanTarget.AtOrigin), SmallPlan() };
            foreach (var plan in plans)
                foreach (var split in DatasetSplits.All)
                {
                    var ours = BlenderTransformsWriter.Write(plan, split);
                    Assert.That(ours, Is.EqualTo(Reserialised(ours)), DatasetSplits.Name(split));
                }
            Assert.That(BlenderTransformsWriter.Write(plans[0], DatasetSplit.Train), Does.Contain("\"camera_id\": 2,").And.Contain("\"normal_path\": \"./train/r_8_normal_0000.png\""));
            Assert.That(BlenderTransformsWriter.Write(plans[1], DatasetSplit.Val), Does.EndWith("\"frames\": []\n}\n"));
        }

        static string Reserialised(string json)
        {
            using (var text = JsonNumbers.CreateText())
            {
                using (var w = JsonNumbers.CreateWriter(text, 4)) JsonNumbers.WriteToken(w, JToken.Parse(json));
                return text + "\n";
            }
        }

        [Test]
        public void AnEmptySplitStillGetsAFileWithAnEmptyFrameList()
        {
            var val = JObject.Parse(BlenderTransformsWriter.Write(SmallPlan(), DatasetSplit.Val));
            Assert.That(val["frames"], Is.InstanceOf<JArray>());
            Assert.That(((JArray)val["frames"]).Count, Is.EqualTo(0));
            Assert.That((double)val["camera_angle_x"], Is.GreaterThan(0));
        }

        [Test]
        public void MatricesReadBackBitExact()
        {
            var plan = CapturePlan.Build(new DatasetSettings(), PlanTarget.AtOrigin);
            var doc = DatasetFolder.Read(BlenderTransformsWriter.Write(plan, DatasetSplit.Test));
            var views = plan.ViewsOf(DatasetSplit.Test).ToList();
            Assert.That(doc.Frames, Has.Count.EqualTo(200));
            for (var i = 0; i < views.Count; i++)
            {
                Assert.That(doc.Frames[i].FilePath, Is.EqualTo(views[i].FramePath));
                Assert.That(doc.Frames[i].TransformMatrix.Value, Is.EqualTo(Normalised(views[i].TransformMatrix)));
            }
        }

        // The writer prints −0 as 0.0; every other entry must come back bit for bit.
        static Matrix4x4d Normalised(Matrix4x4d m)
        {
            var rows = m.ToRows();
            foreach (var row in rows)
                for (var c = 0; c < 4; c++)
                    if (row[c] == 0) row[c] = 0;
            return Matrix4x4d.FromRows(rows);
        }

        [Test]
        public void UsesUnixLineEndsAndNoCultureSpecificText()
        {
            var saved = System.Globalization.CultureInfo.CurrentCulture;
            try
            {
                System.Globalization.CultureInfo.CurrentCulture = new System.Globalization.CultureInfo("fr-FR");
                var text = BlenderTransformsWriter.Write(SmallPlan(), DatasetSplit.Train);
                Assert.That(text, Does.Not.Contain("\r"));
                Assert.That(text, Does.Contain("\"cx\": 200.0,"));
            }
            finally
            {
                System.Globalization.CultureInfo.CurrentCulture = saved;
            }
        }
    }
}
