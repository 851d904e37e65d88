using System;
using System.Diagnostics;
using System.IO;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// Exact flow (issue 37, Core/Features/Flow): a 100k-triangle target — a UV sphere of radius 1 with a wavy surface —
    /// turning by 3° and moving between two steps, seen by one 800×800 camera at distance 3 with nerf_synthetic's field of
    /// view; one view's forward flow with occlusion (a cast per pixel into the mesh at t, a cast per visible point into
    /// the mesh at t′), single thread, CPU time; the BVH build separately; then the same on 1 and 2 threads in wall time and
    /// a pair's files, and the issue's figure — 300 views, forward and backward pairs — extrapolated from the one view.
    /// With --dump-flow DIR the mesh and the primary rays are written for flow_anchor.c (Embree 3's rtcIntersect1, the
    /// caster inside Open3D's RaycastingScene, on the same rays and mesh, one thread).
    /// </summary>
    static class FlowBenchmark
    {
        const int Size = 800, Rings = 158, Segments = 316;
        const double CameraAngleX = 0.6911112070083618; // nerf_synthetic's

        public static void Run(Action<string, double> record, int rounds, string dump)
        {
            Mesh(out var vertices, out var triangles);
            var moved = Moved(vertices);
            var focal = 0.5 * Size / Math.Tan(0.5 * CameraAngleX);
            var eye = new Vector3d(0.4, -2.9, 0.8);
            var forward = (-eye).Normalized();
            var right = Vector3d.Cross(forward, Vector3d.UnitZ).Normalized();
            var up = Vector3d.Cross(right, forward);
            var cameraToWorld = Matrix4x4d.FromColumns(right, up, -forward, eye);
            var camera = new FlowCamera(cameraToWorld, focal, focal, Size / 2.0, Size / 2.0, Size, Size);
            if (dump != null) Dump(dump, vertices, triangles, camera, eye);
            if (rounds == 0) return;

            var process = Process.GetCurrentProcess();
            double build = double.MaxValue, view = double.MaxValue, primary = double.MaxValue;
            FlowField field = null;
            var primaryHits = 0;
            for (var round = 0; round < rounds; round++)
            {
                var t0 = Cpu(process);
                var flow = new SurfaceFlow(vertices, moved, triangles);
                var t1 = Cpu(process);
                field = flow.Image(camera, camera);
                var t2 = Cpu(process);
                // The primary rays alone, as the anchor casts them: the like-for-like figure.
                var bvh = TriangleBvh.Build(vertices, triangles);
                var t3 = Cpu(process);
                primaryHits = 0;
                for (var y = 0; y < Size; y++)
                    for (var x = 0; x < Size; x++)
                    {
                        camera.Ray(x + 0.5, y + 0.5, out var dx, out var dy, out var dz);
                        if (bvh.Intersect(eye.X, eye.Y, eye.Z, dx, dy, dz, 0, double.PositiveInfinity, out _)) primaryHits++;
                    }
                var t4 = Cpu(process);
                build = Math.Min(build, t1 - t0);
                view = Math.Min(view, t2 - t1);
                primary = Math.Min(primary, t4 - t3);
            }
            // The capture's figure: rows on 1 and 2 threads (wall time: CPU time cannot show threads), and a pair's files
            // as FlowWriter writes them (.flo, two PNG masks, the scene-flow EXR) on one thread.
            var wall = new double[3];
            var cpu = new double[3];
            var writeMs = double.MaxValue;
            var same = true;
            var bench = new SurfaceFlow(vertices, moved, triangles);
            var folder = Path.Combine(Path.GetTempPath(), "nerf-flow-bench-" + Guid.NewGuid().ToString("N"));
            try
            {
                wall[1] = wall[2] = cpu[1] = cpu[2] = double.MaxValue;
                // Interleaved, so that a change in the machine's load falls on both thread counts alike.
                for (var round = 0; round < rounds; round++)
                    for (var threads = 1; threads <= 2; threads++)
                    {
                        var c0 = Cpu(process);
                        var clock = Stopwatch.StartNew();
                        var f = bench.Image(camera, camera, threads);
                        wall[threads] = Math.Min(wall[threads], clock.Elapsed.TotalMilliseconds);
                        cpu[threads] = Math.Min(cpu[threads], Cpu(process) - c0);
                        if (threads == 2) same &= SameField(f, field);
                    }
                for (var round = 0; round < rounds; round++)
                {
                    var root = Path.Combine(folder, round.ToString(System.Globalization.CultureInfo.InvariantCulture));
                    Directory.CreateDirectory(Path.Combine(root, "flow", "bench"));
                    var t0 = Cpu(process);
                    FlowWriter.WritePair(root, new FlowPair("bench", 0, 1), field, true);
                    writeMs = Math.Min(writeMs, Cpu(process) - t0);
                }
            }
            finally
            {
                if (Directory.Exists(folder)) Directory.Delete(folder, true);
            }
            int surface = 0, visible = 0, hidden = 0;
            foreach (var s in field.State)
            {
                if (s != (byte)FlowState.NoSurface) surface++;
                if (s == (byte)FlowState.Visible) visible++;
                if (s == (byte)FlowState.Hidden) hidden++;
            }
            var rays = Size * Size + visible + hidden;
            Console.WriteLine($"Flow: {triangles.Length / 3:N0}-triangle target, one {Size}×{Size} view, forward flow with occlusion; single thread, the fastest of {rounds} rounds:");
            Console.WriteLine($"  BVH build, both steps:       {build,8:F0} ms");
            Console.WriteLine($"  one view's flow:             {view,8:F0} ms  ({rays:N0} casts: {Size * Size:N0} primary, {visible + hidden:N0} occlusion; {view * 1e6 / rays:F0} ns a cast)");
            Console.WriteLine($"  the {Size * Size:N0} primary rays alone:  {primary,8:F0} ms  ({primary * 1e6 / (Size * Size):F0} ns a ray, {primaryHits:N0} hits)");
            Console.WriteLine($"  pixels on the target {surface:N0}: visible at t′ {visible:N0}, hidden {hidden:N0}; 300 views ≈ {300 * view / 1000:F0} s");
            Console.WriteLine($"  one view's flow, CPU time:    {cpu[1],8:F0} ms on 1 thread, {cpu[2]:F0} ms on 2 (the same field: {same})");
            Console.WriteLine($"  one view's flow, wall time:   {wall[1],8:F0} ms on 1 thread, {wall[2]:F0} ms on 2 ({wall[1] / wall[2]:F2}×; meaningful only on an idle machine)");
            Console.WriteLine($"  one pair's files (.flo, 2 PNG, EXR): {writeMs,8:F0} ms CPU");
            // 300 views of one video with the default settings: 299 forward + 299 backward pairs, a BVH per step.
            const int Views = 300, Pairs = 2 * (Views - 1);
            // From CPU time (wall time on a shared machine measures its load, not the code): on 1 thread the cast's CPU
            // time; on 2 threads its CPU time (the same work plus the threads' overhead) shared by 2 idle cores.
            for (var threads = 1; threads <= 2; threads++)
                Console.WriteLine($"  300 views, 800×800, forward + backward ({Pairs} pairs), {threads} thread{(threads == 1 ? "" : "s")}: ≈ {Total(threads) / 1000:F0} s " +
                                  $"(= {Views} × {build / 2:F0} ms BVH + {Pairs} × ({Cast(threads):F0} ms cast + {writeMs:F0} ms files); extrapolated from one view{(threads == 1 ? "" : ", 2 idle cores")})");
            Console.WriteLine();
            double Cast(int threads) => threads == 1 ? cpu[1] : cpu[2] / 2;
            double Total(int threads) => Views * build / 2 + Pairs * (Cast(threads) + writeMs);
            record("flow.view.cpu1.ms", cpu[1]);
            record("flow.view.cpu2.ms", cpu[2]);
            record("flow.view.wall1.ms", wall[1]);
            record("flow.view.wall2.ms", wall[2]);
            record("flow.pair.write.ms", writeMs);
            record("flow.video300.t1.s", Total(1) / 1000);
            record("flow.video300.t2.s", Total(2) / 1000);
            record("flow.build.ms", build);
            record("flow.view.ms", view);
            record("flow.cast.ns", view * 1e6 / rays);
            record("flow.300.s", 300 * view / 1000);
            record("flow.surface", surface);
            record("flow.primary.ms", primary);
            record("flow.primary.ns", primary * 1e6 / (Size * Size));
        }

        static bool SameField(FlowField a, FlowField b)
        {
            for (var i = 0; i < a.Flow.Length; i++)
                if (!a.Flow[i].Equals(b.Flow[i])) return false; // Equals: NaN equals NaN
            for (var i = 0; i < a.State.Length; i++)
                if (a.State[i] != b.State[i]) return false;
            return true;
        }

        /// <summary>A wavy UV sphere (radius 1 ± 0.05): 2·Segments·(Rings − 1) triangles.</summary>
        static void Mesh(out double[] vertices, out int[] triangles)
        {
            vertices = new double[3 * (Rings + 1) * Segments];
            var k = 0;
            for (var r = 0; r <= Rings; r++)
            {
                var theta = Math.PI * r / Rings;
                for (var s = 0; s < Segments; s++)
                {
                    var phi = 2 * Math.PI * s / Segments;
                    var radius = 1 + 0.05 * Math.Sin(7 * phi) * Math.Sin(5 * theta);
                    vertices[k++] = radius * Math.Sin(theta) * Math.Cos(phi);
                    vertices[k++] = radius * Math.Sin(theta) * Math.Sin(phi);
                    vertices[k++] = radius * Math.Cos(theta);
                }
            }
            triangles = new int[3 * 2 * Segments * (Rings - 1)];
            k = 0;
            for (var r = 0; r < Rings; r++)
                for (var s = 0; s < Segments; s++)
                {
                    int a = r * Segments + s, b = r * Segments + (s + 1) % Segments, c = a + Segments, d = b + Segments;
                    if (r > 0) { triangles[k++] = a; triangles[k++] = c; triangles[k++] = b; }
                    if (r < Rings - 1) { triangles[k++] = b; triangles[k++] = c; triangles[k++] = d; }
                }
        }

        /// <summary>The mesh turned 3° about +Z and moved by (0.02, 0, 0.01).</summary>
        static double[] Moved(double[] vertices)
        {
            var moved = new double[vertices.Length];
            double c = Math.Cos(3 * Math.PI / 180), s = Math.Sin(3 * Math.PI / 180);
            for (var i = 0; i < vertices.Length; i += 3)
            {
                moved[i] = c * vertices[i] - s * vertices[i + 1] + 0.02;
                moved[i + 1] = s * vertices[i] + c * vertices[i + 1];
                moved[i + 2] = vertices[i + 2] + 0.01;
            }
            return moved;
        }

        /// <summary>vertices.f64, triangles.i32 and rays.f32 (ox oy oz dx dy dz per pixel, as Open3D's cast_rays takes them).</summary>
        static void Dump(string folder, double[] vertices, int[] triangles, FlowCamera camera, Vector3d eye)
        {
            Directory.CreateDirectory(folder);
            var v = new byte[vertices.Length * 8];
            Buffer.BlockCopy(vertices, 0, v, 0, v.Length);
            File.WriteAllBytes(Path.Combine(folder, "vertices.f64"), v);
            var t = new byte[triangles.Length * 4];
            Buffer.BlockCopy(triangles, 0, t, 0, t.Length);
            File.WriteAllBytes(Path.Combine(folder, "triangles.i32"), t);
            var rays = new float[Size * Size * 6];
            for (var y = 0; y < Size; y++)
                for (var x = 0; x < Size; x++)
                {
                    camera.Ray(x + 0.5, y + 0.5, out var dx, out var dy, out var dz);
                    var k = 6 * (y * Size + x);
                    rays[k] = (float)eye.X; rays[k + 1] = (float)eye.Y; rays[k + 2] = (float)eye.Z;
                    rays[k + 3] = (float)dx; rays[k + 4] = (float)dy; rays[k + 5] = (float)dz;
                }
            var r = new byte[rays.Length * 4];
            Buffer.BlockCopy(rays, 0, r, 0, r.Length);
            File.WriteAllBytes(Path.Combine(folder, "rays.f32"), r);
        }

        static double Cpu(Process process)
        {
            process.Refresh();
            return process.TotalProcessorTime.TotalMilliseconds;
        }
    }
}
