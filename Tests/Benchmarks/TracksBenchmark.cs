using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using NerfDatasetCreator.Tests;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// Exact COLMAP tracks (ColmapVisibility) for 100 000 surface points over 300 views of 800×800, from real 16-bit
    /// depth PNGs and 8-bit masks of an analytic two-sphere target (the tests' SphereScene, linked) seen from the
    /// upper hemisphere at distance 4 with nerf_synthetic's field of view. The files are written once into a temp
    /// folder (not timed, in parallel); then each round decodes every depth map and mask once and projects every point
    /// into each view, single thread, timing the decoding and the projection separately (CPU time). Also: how many points each
    /// view keeps tracked with the default minimum track length, and the CPU time of writing the model (binary and
    /// text) into a stream that only counts bytes.
    /// </summary>
    static class TracksBenchmark
    {
        const int Views = 300, Size = 800, Points = 100000;
        const double Distance = 4, CameraAngleX = 0.6911112070083618; // nerf_synthetic's

        public static void Run(Action<string, double> record, int rounds)
        {
            var root = Path.Combine(Path.GetTempPath(), "nerf-bench-tracks-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(root);
            try
            {
                var k = CameraIntrinsics.FromVerticalFov(CameraIntrinsics.VerticalFovDegreesFromHorizontal(CameraAngleX, Size, Size), Size, Size);
                var target = SphereScene.TwoSpheres();
                var frames = new ExportFrame[Views];
                var generation = Stopwatch.StartNew();
                Parallel.For(0, Views, v =>
                {
                    // Fibonacci points on the upper hemisphere: even coverage, no camera exactly at the pole.
                    var z = 1 - (v + 0.5) / Views;
                    var azimuth = v * Math.PI * (3 - Math.Sqrt(5));
                    var rho = Math.Sqrt(1 - z * z);
                    var c2w = SphereScene.LookAt(new Vector3d(Distance * rho * Math.Cos(azimuth), Distance * rho * Math.Sin(azimuth), Distance * z), Vector3d.Zero);
                    target.Render(c2w, k, out var depth, out var mask, out _);
                    File.WriteAllBytes(Path.Combine(root, "r_" + v + "_depth_0000.png"), PngWriter.EncodeGray16(depth, Size, Size));
                    File.WriteAllBytes(Path.Combine(root, "r_" + v + "_mask_0000.png"), PngWriter.Encode(mask, Size, Size, PngPixelFormat.Gray8));
                    frames[v] = new ExportFrame("train", "r_" + v + ".png", c2w, "r_" + v + "_depth_0000.png", "r_" + v + "_mask_0000.png");
                });
                var scene = new ExportScene(root, k, frames);
                var cloud = target.Sample(Points, 1);
                Console.WriteLine($"COLMAP tracks: {Points / 1000} 000 points (two spheres, radius 1 and 0.35) over {Views} views of {Size}×{Size} from the upper hemisphere at distance {Distance}");
                Console.WriteLine($"(depth + mask PNGs written in {generation.Elapsed.TotalSeconds:F1} s, not timed); single thread, the fastest of {rounds} rounds:");

                // ColmapVisibility.Compute's own loop (decode each map once, then one pass over the points), timed in
                // CPU time of the process per phase: the machine is shared, and wall time would count others' work.
                double decode = double.MaxValue, project = double.MaxValue;
                int[][] observations = null;
                var process = Process.GetCurrentProcess();
                var arrays = new ColmapVisibility.PointArrays(cloud);
                var visible = new List<int>();
                for (var round = 0; round < rounds; round++)
                {
                    double decodeMs = 0, projectMs = 0;
                    observations = new int[Views][];
                    for (var v = 0; v < Views; v++)
                    {
                        var t0 = Cpu(process);
                        var depth = PngGray16Reader.Read(Path.Combine(root, frames[v].DepthPath), out _, out _);
                        var mask = PngReader.Read(Path.Combine(root, frames[v].MaskPath)).Samples;
                        var t1 = Cpu(process);
                        ColmapVisibility.Observe(ColmapPose.FromCameraToWorld(frames[v].CameraToWorld), k, depth, mask, scene.DepthUnitScale, arrays, visible);
                        observations[v] = visible.ToArray();
                        var t2 = Cpu(process);
                        decodeMs += t1 - t0;
                        projectMs += t2 - t1;
                    }
                    decode = Math.Min(decode, decodeMs);
                    project = Math.Min(project, projectMs);
                }
                var check = ColmapVisibility.Compute(scene, cloud);
                for (var v = 0; v < Views; v++)
                    if (!check[v].SequenceEqual(observations[v])) throw new InvalidOperationException("Compute and the timed loop disagree on view " + v + ".");
                var names = Enumerable.Range(0, Views).Select(v => "r_" + v + ".png").ToList();
                var poses = frames.Select(f => ColmapPose.FromCameraToWorld(f.CameraToWorld)).ToList();
                var model = ColmapModelBuilder.KeepTracked(k, names, poses, cloud, observations, ColmapOptions.DefaultMinTrackLength);
                var perView = model.Observations.Select(o => o.Length).OrderBy(n => n).ToArray();

                var writeBinary = double.MaxValue;
                var writeText = double.MaxValue;
                long binaryBytes = 0, textBytes = 0;
                for (var round = 0; round < rounds; round++)
                {
                    var t0 = Cpu(process);
                    var images = new CountingStream();
                    var points = new CountingStream();
                    ColmapBinaryWriter.WriteImages(images, model);
                    ColmapBinaryWriter.WritePoints3D(points, model);
                    var t1 = Cpu(process);
                    writeBinary = Math.Min(writeBinary, t1 - t0);
                    binaryBytes = images.Length + points.Length;
                    var text = new CountingStream();
                    using (var writer = new StreamWriter(text))
                    {
                        ColmapTextWriter.WriteImages(writer, model);
                        ColmapTextWriter.WritePoints3D(writer, model);
                    }
                    writeText = Math.Min(writeText, Cpu(process) - t1);
                    textBytes = text.Length;
                }

                Console.WriteLine($"  decoding {Views} depth maps + {Views} masks:      {decode,8:F0} ms  ({decode / Views:F2} ms a view)");
                Console.WriteLine($"  projecting and testing every point:     {project,8:F0} ms  ({project * 1e6 / ((double)Points * Views):F1} ns a point and view)");
                Console.WriteLine($"  observations: {observations.Sum(o => o.Length):N0} before, {model.ObservationCount:N0} after dropping points seen by fewer than {ColmapOptions.DefaultMinTrackLength} views ({model.Points.Count:N0} points kept, mean track {model.MeanTrackLength:F1})");
                Console.WriteLine($"  tracked points per view: min {perView[0]}, median {perView[perView.Length / 2]}, max {perView[perView.Length - 1]}");
                foreach (var first in new[] { 10000, 1000 })
                {
                    // A track does not depend on the other points: the first N points' model is this one's restricted to them.
                    var sparse = ColmapModelBuilder.KeepTracked(k, names, poses, cloud.Take(first).ToList(),
                        observations.Select(o => o.Where(p => p < first).ToArray()).ToArray(), ColmapOptions.DefaultMinTrackLength);
                    var counts = sparse.Observations.Select(o => o.Length).OrderBy(n => n).ToArray();
                    Console.WriteLine($"  with --points {first}: min {counts[0]}, median {counts[counts.Length / 2]} tracked points per view");
                    record("tracks.view.min." + first, counts[0]);
                }
                Console.WriteLine($"  writing images + points3D: binary {writeBinary:F0} ms ({binaryBytes / 1e6:F0} MB), text {writeText:F0} ms ({textBytes / 1e6:F0} MB)");
                Console.WriteLine();
                record("tracks.decode.ms", decode);
                record("tracks.decode.view.ms", decode / Views);
                record("tracks.project.ms", project);
                record("tracks.project.ns", project * 1e6 / ((double)Points * Views));
                record("tracks.view.min", perView[0]);
                record("tracks.view.median", perView[perView.Length / 2]);
                record("tracks.write.bin.ms", writeBinary);
                record("tracks.write.text.ms", writeText);
            }
            finally
            {
                Directory.Delete(root, true);
            }
        }

        static double Cpu(Process process)
        {
            process.Refresh();
            return process.TotalProcessorTime.TotalMilliseconds;
        }

        /// <summary>Counts what is written and keeps nothing: the writers' own cost, without a disk.</summary>
        sealed class CountingStream : Stream
        {
            long _length;
            public override bool CanRead => false;
            public override bool CanSeek => false;
            public override bool CanWrite => true;
            public override long Length => _length;
            public override long Position { get => _length; set => throw new NotSupportedException(); }
            public override void Flush() { }
            public override int Read(byte[] buffer, int offset, int count) => throw new NotSupportedException();
            public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
            public override void SetLength(long value) => throw new NotSupportedException();
            public override void Write(byte[] buffer, int offset, int count) => _length += count;
        }
    }
}
