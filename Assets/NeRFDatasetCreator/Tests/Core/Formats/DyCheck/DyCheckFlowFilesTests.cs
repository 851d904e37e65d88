using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// DyCheck's covisible/ and keypoint/ from flow/, read back as KAIR-BAIR/dycheck ddf77a4 reads them —
    /// datasets/nerfies.py load_covisible (204–256: cv2.imread, [..., :1]) and load_keypoints (258–311: the (J, 3) list,
    /// + 0.5 with the camera's use_center, geometry/camera.py:280), load_skeleton (313–336), core/tasks/kp_transfer.py
    /// get_kp_dataset (37–79: utils/common.py strided_subset, 148–156) — and checked against the depth EXRs and poses.
    /// </summary>
    public class DyCheckFlowFilesTests
    {
        static AnalyticDataset.Options Options(bool monocular) => new AnalyticDataset.Options
        {
            Width = 64, Height = 48, Supersampling = 1, Train = monocular ? 10 : 2, Val = 1, Test = 1,
            TimeSteps = monocular ? 10 : 3, Monocular = monocular, PointCloud = 0,
            MeshesAt = AnalyticSceneMeshes.At, GeometryPackEveryStep = true,
            Configure = s => { foreach (var split in new[] { s.Train, s.Val, s.Test }) split.Depth = ExtraOutput.PngAndExr; },
        };

        [Test]
        public void AMonocularCapturesKeypointsAreItsTracksAtDyChecksTenStridedTrainFrames()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "mono", Options(monocular: true));
                FlowWriter.Write(folder, new FlowSettings { On = true, TrackQueryFrames = new[] { 0 }, TrackStride = 4 });
                var output = temp.Combine("dycheck");
                var result = DatasetConverter.Convert(folder, ExportTarget.Dycheck, output);
                Assert.That(result.Warnings.Select(w => w.Field), Has.No.Member("keypoint").And.No.Member("flow"));
                var ours = FlowTracksFile.Read(Path.Combine(folder, FlowRecord.Read(folder).Tracks.Single().File));
                var train = JObject.Parse(File.ReadAllText(Path.Combine(output, "splits", "train.json")));
                var names = train["frame_names"].Select(t => (string)t).ToList();
                // strided_subset(frame_names, 10): np.linspace(0, 10, 10, endpoint=False, dtype=int).
                var keypointFrames = names.Where((n, i) => new[] { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9 }.Contains(i)).ToList();
                var visible = 0;
                foreach (var name in keypointFrames)
                {
                    var position = int.Parse(name.Split('_')[1]);
                    var rows = JArray.Parse(File.ReadAllText(Path.Combine(output, "keypoint", "1x", "train", name + ".json")));
                    Assert.That(rows.Count, Is.EqualTo(ours.Points));
                    for (var p = 0; p < ours.Points; p++)
                    {
                        // load_keypoints: keypoints[:, :2] + offset (0.5: use_center), keypoints[:, -1:].
                        double x = (double)rows[p][0] + 0.5, y = (double)rows[p][1] + 0.5, v = (double)rows[p][2];
                        if (ours.StateAt(position, p) != FlowState.Visible)
                        {
                            Assert.That(v, Is.EqualTo(0));
                            continue;
                        }
                        Assert.That(v, Is.EqualTo(1));
                        Assert.That(x, Is.EqualTo(ours.X(position, p)).Within(1e-4));
                        Assert.That(y, Is.EqualTo(ours.Y(position, p)).Within(1e-4));
                        visible++;
                    }
                }
                Assert.That(visible, Is.GreaterThan(100));
                // load_skeleton: Skeleton(parents, kp_names, palette) with len(parents) == len(kp_names) == len(palette).
                var skeleton = JObject.Parse(File.ReadAllText(Path.Combine(output, "keypoint", "1x", "train", "skeleton.json")));
                Assert.That(((JArray)skeleton["parents"]).Count, Is.EqualTo(ours.Points));
                Assert.That(skeleton["parents"].All(t => t.Type == JTokenType.Null), Is.True, "is_unconnected: no bones");
                Assert.That(((JArray)skeleton["kp_names"]).Count, Is.EqualTo(ours.Points));
                Assert.That(((JArray)skeleton["palette"]).Count, Is.EqualTo(ours.Points));
                // A test view at a train time is a val view (camera 1): it gets its covisible mask too.
                var valNames = JObject.Parse(File.ReadAllText(Path.Combine(output, "splits", "val.json")))["frame_names"].Select(t => (string)t).ToList();
                Assert.That(Directory.GetFiles(Path.Combine(output, "covisible", "1x", "val")).Select(Path.GetFileNameWithoutExtension), Is.EquivalentTo(valNames));
            }
        }

        [Test]
        public void AMultiViewCapturesCovisibleMasksAgreeWithTheAnalyticSceneSeenFromEveryTrainView()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "multi", Options(monocular: false));
                FlowWriter.Write(folder, new FlowSettings { On = true, TrackQueryFrames = new[] { 0 }, TrackStride = 8 });
                var output = temp.Combine("dycheck");
                var result = DatasetConverter.Convert(folder, ExportTarget.Dycheck, output);
                Assert.That(result.Warnings.Single(w => w.Field == "keypoint").Reason, Does.Contain("several cameras"));
                var scene = BlenderDatasetLoader.Load(folder);
                var k = scene.Intrinsics;
                var normalisation = SceneNormalisation.FromJson(JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")))["scene_normalisation"]);
                AnalyticScene At(ExportFrame f) => AnalyticScene.Layout(normalisation, AnalyticDataset.Centre, f.Time.Value);
                var trainFrames = scene.Split("train").ToList();
                Assert.That(trainFrames.Count, Is.EqualTo(6));
                // process_covisible.py:155–158: not co-visible when seen in at most max(5, int(0.1 · S)) training images.
                var threshold = Math.Max(5, (int)(0.1 * trainFrames.Count));
                var val = JObject.Parse(File.ReadAllText(Path.Combine(output, "splits", "val.json")));
                var valNames = val["frame_names"].Select(t => (string)t).ToList();
                Assert.That(valNames.Count, Is.EqualTo(3));
                int judged = 0, agree = 0, hidden = 0;
                foreach (var name in valNames)
                {
                    // load_covisible: cv2.imread (3 channels), [..., :1]; image.to_float32 → 0 or 1.
                    var mask = PngReader.Read(Path.Combine(output, "covisible", "1x", "val", name + ".png"));
                    Assert.That((mask.Width, mask.Height), Is.EqualTo((64, 48)));
                    var frame = scene.Split("test").Single(f => f.Timing.Step == int.Parse(name.Split('_')[1]));
                    var analytic = At(frame);
                    var centre = frame.CameraToWorld.MultiplyPoint(Vector3d.Zero);
                    for (var v = 0; v < 48; v++)
                        for (var u = 0; u < 64; u++)
                        {
                            var p = v * 64 + u;
                            // NeRF's get_rays: ((i − cx)/f, −(j − cy)/f, −1) in camera space through the pixel centre.
                            var through = frame.CameraToWorld.MultiplyPoint(new Vector3d((u + 0.5 - k.Cx) / k.FlX, -(v + 0.5 - k.Cy) / k.FlY, -1));
                            if (!analytic.Trace(centre, (through - centre).Normalized(), 0, out var t, out _, out _, out _, out var id))
                            {
                                Assert.That(mask.Samples[p], Is.EqualTo(255), "off the target: co-visible");
                                continue;
                            }
                            if (id == 1) continue; // the moving sphere: its point is elsewhere at other times
                            var point = centre + (through - centre).Normalized() * t;
                            var seen = trainFrames.Count(f => Sees(At(f), f, k, point));
                            judged++;
                            if ((seen > threshold) == (mask.Samples[p] == 255)) agree++;
                            if (mask.Samples[p] == 0) hidden++;
                        }
                }
                Assert.That(judged, Is.GreaterThan(1000));
                // The meshes are UV spheres and the analytic spheres exact: a few silhouette pixels may differ.
                Assert.That(agree, Is.GreaterThan(judged * 98 / 100), agree + " of " + judged);
                Assert.That(hidden, Is.GreaterThan(50), "some static surface is hidden from a train view");
            }
        }

        /// <summary>Whether the camera of <paramref name="frame"/> sees <paramref name="point"/> of the analytic scene: in its image and first on its ray.</summary>
        static bool Sees(AnalyticScene scene, ExportFrame frame, CameraIntrinsics k, Vector3d point)
        {
            var c = frame.CameraToWorld.InverseRigid().MultiplyPoint(point);
            if (c.Z >= 0) return false;
            double x = k.FlX * c.X / -c.Z + k.Cx, y = -k.FlY * c.Y / -c.Z + k.Cy;
            if (x < 0 || y < 0 || x >= k.Width || y >= k.Height) return false;
            var centre = frame.CameraToWorld.MultiplyPoint(Vector3d.Zero);
            var distance = Vector3d.Distance(point, centre);
            return !scene.Trace(centre, (point - centre).Normalized(), 0, out var t, out _, out _, out _) || t >= distance * (1 - 1e-6);
        }
    }
}
