using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// flow/ written from an analytic dynamic dataset (its geometry pack every step) and checked against what the
    /// dataset's own files say independently: the transforms poses read as NeRF reads them, the analytic depth EXRs, and
    /// the analytic motion (only the opaque sphere moves, 0.4 along Unity +X = output +X over the whole time range).
    /// </summary>
    public class FlowWriterTests
    {
        static AnalyticDataset.Options Options(bool monocular) => new AnalyticDataset.Options
        {
            Width = 64, Height = 48, Supersampling = 1, Train = monocular ? 5 : 2, Val = 1, Test = 1,
            TimeSteps = monocular ? 5 : 3, Monocular = monocular, PointCloud = 0,
            MeshesAt = AnalyticSceneMeshes.At, GeometryPackEveryStep = true,
            Configure = s => { foreach (var split in new[] { s.Train, s.Val, s.Test }) split.Depth = ExtraOutput.PngAndExr; },
        };

        static FlowSettings Settings() => new FlowSettings { On = true, TrackQueryFrames = new[] { 0 }, TrackStride = 4 };

        [Test]
        public void MonocularHasOneVideoOfTheTrainSplitAndEveryPairsFiles()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "mono", Options(monocular: true));
                FlowWriter.Write(folder, Settings());
                var record = FlowRecord.Read(folder);
                Assert.That(record.Videos.Select(v => v.Name), Is.EqualTo(new[] { "train" }));
                Assert.That(record.Videos[0].Frames.Select(f => f.Image), Is.EqualTo(Enumerable.Range(0, 5).Select(i => "train/r_" + i + ".png")));
                Assert.That(record.Videos[0].Frames.Select(f => f.Step), Is.EqualTo(new[] { 0, 1, 2, 3, 4 }));
                Assert.That(record.Pairs.Count, Is.EqualTo(8), "4 forward and 4 backward pairs of 5 frames");
                foreach (var p in record.Pairs)
                    foreach (var f in new[] { p.FlowFile, p.OccludedFile, p.OutsideFile, p.SceneFlowFile })
                        Assert.That(File.Exists(Path.Combine(folder, f)), Is.True, f);
                Assert.That(record.Pairs[0].FlowFile, Is.EqualTo("flow/train/flow_0000_0001.flo"));
            }
        }

        [Test]
        public void StaticSurfacesFlowAsTheDepthAndPosesSayAndTheSphereMovesAsAnimated()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "mono", Options(monocular: true));
                FlowWriter.Write(folder, Settings());
                var record = FlowRecord.Read(folder);
                var transforms = JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")));
                var frames = (JArray)transforms["frames"];
                double w = 64, h = 48, f = 0.5 * w / Math.Tan(0.5 * (double)transforms["camera_angle_x"]);
                var scale = (double)transforms["scene_normalisation"]["scale"];
                int staticChecked = 0, exact = 0, movingChecked = 0;
                foreach (var pair in record.Pairs)
                {
                    var flow = FloFile.Read(Path.Combine(folder, pair.FlowFile), out var fw, out var fh);
                    Assert.That((fw, fh), Is.EqualTo((64, 48)));
                    var scene = ExrReader.Read(Path.Combine(folder, pair.SceneFlowFile));
                    var outside = PngReader.Read(Path.Combine(folder, pair.OutsideFile));
                    var depth = ExrReader.Read(Path.Combine(folder, "train", "r_" + pair.From + "_depth_0000.exr"));
                    var a = Pose(frames[pair.From]);
                    var b = Pose(frames[pair.To]);
                    var dt = (pair.To - pair.From) / 4.0;
                    for (var v = 0; v < 48; v++)
                        for (var u = 0; u < 64; u++)
                        {
                            var p = v * 64 + u;
                            var sf = SceneFlowAt(scene, u, v);
                            if (sf == null)
                            {
                                Assert.That(float.IsNaN(flow[2 * p]), Is.True, "no surface, no flow");
                                continue;
                            }
                            if (outside.Samples[p] != 0) continue;
                            var moving = Math.Abs(sf[0]) > 1e-6;
                            if (moving)
                            {
                                // Only the opaque sphere moves: 0.4 Unity units along +X over the time range.
                                Assert.That(sf[0], Is.EqualTo(0.4 * dt * scale).Within(1e-5), "scene flow x at " + u + "," + v);
                                Assert.That(Math.Abs(sf[1]) + Math.Abs(sf[2]), Is.LessThan(1e-5));
                                movingChecked++;
                                continue;
                            }
                            var z = DepthAt(depth, u, v);
                            if (!(z > 0)) continue;
                            // NeRF's ray (get_rays): dir = ((i − W/2)/f, −(j − H/2)/f, −1) in camera space, i = u + 0.5.
                            double cx = (u + 0.5 - w / 2) / f * z, cy = -(v + 0.5 - h / 2) / f * z, cz = -z;
                            var world = a.MultiplyPoint(new Vector3d(cx, cy, cz));
                            var inB = b.InverseRigid().MultiplyPoint(world);
                            double x2 = f * inB.X / -inB.Z + w / 2, y2 = -f * inB.Y / -inB.Z + h / 2;
                            double ex = x2 - (u + 0.5), ey = y2 - (v + 0.5);
                            var error = Math.Max(Math.Abs(flow[2 * p] - ex), Math.Abs(flow[2 * p + 1] - ey));
                            Assert.That(error, Is.LessThan(0.05), "static pixel " + u + "," + v + " of " + pair.FlowFile);
                            staticChecked++;
                            if (error < 1e-3) exact++;
                        }
                }
                Assert.That(staticChecked, Is.GreaterThan(1000));
                Assert.That(movingChecked, Is.GreaterThan(100));
                // The slab is a box: its facets are the analytic surface, so there the flow is exact; the UV spheres' facets are
                // a few thousandths of a unit off the analytic depth.
                Assert.That(exact, Is.GreaterThan(staticChecked / 4), exact + " of " + staticChecked + " static pixels within 1e-3 px");
            }
        }

        [Test]
        public void MultiViewHasOneVideoPerCameraOfEverySplitWithStaticCamerasAndTracksFollowTheSphere()
        {
            using (var temp = new TempFolder())
            {
                var folder = AnalyticDataset.Write(temp.Path, "multi", Options(monocular: false));
                FlowWriter.Write(folder, Settings());
                var record = FlowRecord.Read(folder);
                Assert.That(record.Videos.Select(v => v.Name), Is.EqualTo(new[] { "train_cam00", "train_cam01", "val_cam00", "test_cam00" }));
                Assert.That(record.Videos.All(v => v.Frames.Select(f => f.Step).SequenceEqual(new[] { 0, 1, 2 })), Is.True);
                Assert.That(record.Tracks.Count, Is.EqualTo(4));
                var path = Path.Combine(folder, record.Tracks[0].File);
                Assert.That(NpzEntries(path), Is.EquivalentTo(new[] { "query_xy.npy", "xy.npy", "state.npy", "points.npy" }));
                var xy = Npy(path, "xy.npy");
                var points = Npy(path, "points.npy");
                int n = record.Tracks[0].Points, moved = 0, still = 0;
                Assert.That(xy.Shape, Is.EqualTo(new[] { 3, n, 2 }));
                var scale = (double)JObject.Parse(File.ReadAllText(Path.Combine(folder, "transforms_train.json")))["scene_normalisation"]["scale"];
                for (var i = 0; i < n; i++)
                {
                    var dx = points.Values[3 * (2 * n + i)] - points.Values[3 * i];
                    if (Math.Abs(dx) < 1e-6)
                    {
                        // A static point seen by a static camera stays where it is, in every frame.
                        Assert.That(xy.Values[2 * (2 * n + i)], Is.EqualTo(xy.Values[2 * i]).Within(1e-4));
                        still++;
                    }
                    else
                    {
                        Assert.That(dx, Is.EqualTo(0.4 * scale).Within(1e-5), "the opaque sphere moves 0.4 along +X from step 0 to 2");
                        moved++;
                    }
                }
                Assert.That(moved, Is.GreaterThan(5));
                Assert.That(still, Is.GreaterThan(5));
            }
        }

        [Test]
        public void AStaticDatasetAndAnExistingFlowFolderAreRefused()
        {
            using (var temp = new TempFolder())
            {
                var o = Options(monocular: true);
                o.TimeSteps = 0;
                o.Monocular = false;
                var folder = AnalyticDataset.Write(temp.Path, "static", o);
                var e = Assert.Throws<InvalidParameterException>(() => FlowWriter.Write(folder, Settings()));
                Assert.That(e.Message, Does.Contain("time"));
                var dynamic = AnalyticDataset.Write(temp.Path, "mono", Options(monocular: true));
                Directory.CreateDirectory(Path.Combine(dynamic, "flow"));
                File.WriteAllText(Path.Combine(dynamic, "flow", "mine.txt"), "the user's");
                e = Assert.Throws<InvalidParameterException>(() => FlowWriter.Write(dynamic, Settings()));
                Assert.That(e.Message, Does.Contain("exists already"));
                Assert.That(File.ReadAllText(Path.Combine(dynamic, "flow", "mine.txt")), Is.EqualTo("the user's"));
            }
        }

        [Test]
        public void FloFilesStartWithPiehAndRoundTrip()
        {
            var flow = new[] { 1.5f, -2.25f, float.NaN, 0f, 3f, 4f };
            var bytes = FloFile.Encode(flow, 3, 1);
            Assert.That(System.Text.Encoding.ASCII.GetString(bytes, 0, 4), Is.EqualTo("PIEH"));
            Assert.That(BitConverter.ToInt32(bytes, 4), Is.EqualTo(3));
            Assert.That(BitConverter.ToInt32(bytes, 8), Is.EqualTo(1));
            Assert.That(bytes.Length, Is.EqualTo(12 + 6 * 4));
            var back = FloFile.Decode(bytes, "x.flo", out var w, out var h);
            Assert.That((w, h), Is.EqualTo((3, 1)));
            Assert.That(back, Is.EqualTo(flow));
            bytes[0] ^= 1;
            Assert.That(() => FloFile.Decode(bytes, "x.flo", out _, out _), Throws.TypeOf<InvalidDataException>().With.Message.Contains("PIEH"));
        }

        static Matrix4x4d Pose(JToken frame)
        {
            var m = (JArray)frame["transform_matrix"];
            return Matrix4x4d.FromRows(m.Select(r => r.Select(x => (double)x).ToArray()).ToArray());
        }

        // EXR rows are stored top row first; ExrImage's pixels as ExrReader gives them (see ExrReader).
        static double[] SceneFlowAt(ExrImage image, int u, int v)
        {
            var a = image.Channel("A")[v * image.Width + u];
            if (a == 0) return null;
            return new double[] { image.Channel("R")[v * image.Width + u], image.Channel("G")[v * image.Width + u], image.Channel("B")[v * image.Width + u] };
        }

        static double DepthAt(ExrImage image, int u, int v) => image.Channel("Y")[v * image.Width + u];

        static NpyReader.NpyArray Npy(string path, string entry)
        {
            using (var zip = System.IO.Compression.ZipFile.OpenRead(path))
            using (var stream = zip.GetEntry(entry).Open())
            using (var memory = new MemoryStream())
            {
                stream.CopyTo(memory);
                return NpyReader.Decode(memory.ToArray(), entry);
            }
        }

        static List<string> NpzEntries(string path)
        {
            using (var zip = System.IO.Compression.ZipFile.OpenRead(path)) return zip.Entries.Select(e => e.FullName).ToList();
        }
    }
}
