using System;

namespace NerfDatasetCreator.Benchmarks
{
    /// <summary>
    /// The id maps of one 800×800 view at supersampling 2 (issue 26): a 1600×1600 id pass with twelve discs of ids over
    /// background (edges in every direction, objects touching), turned into the instance map and the semantic map by the
    /// majority rule (IdMajority), and the instance map encoded as a 16-bit PNG — what ViewFileWriter adds per view.
    /// </summary>
    static class LabelsBenchmark
    {
        const int Size = 800, K = 2;

        public static void Run(Action<string, double> record, Func<(string Name, Action Run)[], double[]> time)
        {
            int w = Size * K;
            var frame = new RawFrame(w, w, K) { InstanceIds = new ushort[w * w] };
            var random = new Random(26);
            for (var disc = 1; disc <= 12; disc++)
            {
                double cx = random.Next(w), cy = random.Next(w), r = 100 + random.Next(300);
                for (var y = 0; y < w; y++)
                    for (var x = 0; x < w; x++)
                        if ((x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r) frame.InstanceIds[y * w + x] = (ushort)disc;
            }
            var classes = new ushort[] { 0, 1, 1, 2, 2, 3, 3, 1, 2, 3, 1, 2, 3 };
            var ids = new ushort[Size * Size];
            Console.WriteLine($"Id maps of one {Size}×{Size} view from a {w}×{w} id pass (supersampling {K}, twelve overlapping discs); ms:");
            var t = time(new (string, Action)[]
            {
                ("instance map, majority rule", () => IdMajority.Resolve(frame, ids)),
                ("semantic map, majority rule over classes", () => IdMajority.Resolve(frame, ids, classes)),
                ("instance map, 16-bit PNG encoding", () => PngWriter.EncodeGray16(ids, Size, Size)),
            });
            record("labels.instance.ms", t[0]);
            record("labels.semantic.ms", t[1]);
            record("labels.png.ms", t[2]);
            Console.WriteLine();
        }
    }
}
