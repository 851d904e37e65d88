using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Writes the folders a sharded capture would leave, without Unity: per shard a shard.json, partial
    /// transforms_*.json whose frames carry every key the writer might add, tiny PNG files whose bytes name their
    /// view (so a test can tell which file landed where), a depth file per test view and a dataset_config.json.
    /// </summary>
    static class ShardFolders
    {
        public const double CameraAngleX = 0.6911112070083618;

        public static string[] Create(string root, int shardCount, ViewCounts counts)
        {
            var folders = new string[shardCount];
            for (var s = 0; s < shardCount; s++)
            {
                var folder = Path.Combine(root, "shard-" + s.ToString(CultureInfo.InvariantCulture));
                Directory.CreateDirectory(folder);
                folders[s] = folder;
                var manifest = ShardManifest.ForShard(new ShardSpec(s, shardCount), counts);
                manifest.Write(folder);
                foreach (var split in ViewCounts.SplitNames)
                {
                    var frames = new JArray();
                    Directory.CreateDirectory(Path.Combine(folder, split));
                    foreach (var i in manifest.Views(split))
                    {
                        frames.Add(Frame(split, i));
                        File.WriteAllBytes(Path.Combine(folder, split, "r_" + i + ".png"), ImageBytes(split, i));
                        if (split == "test") File.WriteAllBytes(Path.Combine(folder, split, "r_" + i + "_depth.png"), ImageBytes(split + "-depth", i));
                    }
                    var transforms = new JObject
                    {
                        ["camera_angle_x"] = CameraAngleX,
                        ["w"] = 8,
                        ["h"] = 8,
                        ["frames"] = frames,
                        ["aabb_scale"] = 1,
                    };
                    WriteJson(Path.Combine(folder, "transforms_" + split + ".json"), transforms);
                }
                // Per-run keys (date, images rendered, timings) differ between shards, as a real capture writes them.
                WriteJson(Path.Combine(folder, "dataset_config.json"), new JObject
                {
                    ["pluginVersion"] = "0.1.0",
                    ["unityVersion"] = "2022.3.62f1",
                    ["imagesRendered"] = true, // a boolean, as DatasetConfig.Write writes it
                    ["createdUtc"] = "2026-01-0" + (s % 9 + 1).ToString(CultureInfo.InvariantCulture) + "T10:00:00.000Z",
                    ["statistics"] = new JObject { ["secondsPerView"] = 0.5 + s },
                    ["seed"] = 42,
                    ["settings"] = new JObject { ["width"] = 8, ["height"] = 8 },
                });
            }
            return folders;
        }

        public static JObject Frame(string split, int i)
        {
            var frame = new JObject
            {
                ["file_path"] = "./" + split + "/r_" + i,
                ["rotation"] = 0.012566370614359171,
                ["transform_matrix"] = new JArray(
                    new JArray(1.0, 0.0, 0.0, (double)i), new JArray(0.0, 1.0, 0.0, 0.5),
                    new JArray(0.0, 0.0, 1.0, 4.0), new JArray(0.0, 0.0, 0.0, 1.0)),
                ["view_note"] = split + ":" + i,
            };
            if (split == "test") frame["depth_path"] = "./test/r_" + i + "_depth.png";
            return frame;
        }

        /// <summary>The PNG signature followed by the view's name: unique per view, recognisably a placeholder.</summary>
        public static byte[] ImageBytes(string split, int i) =>
            new byte[] { 0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A }.Concat(Encoding.ASCII.GetBytes(split + "/" + i)).ToArray();

        /// <summary>Reads a JSON file keeping date-like strings as text (Newtonsoft would parse them as DateTime).</summary>
        public static JObject ReadJson(string path)
        {
            using (var reader = new JsonTextReader(new StringReader(File.ReadAllText(path))) { DateParseHandling = DateParseHandling.None })
                return JObject.Load(reader);
        }

        public static void WriteJson(string path, JToken json) => File.WriteAllText(path, json.ToString(Formatting.Indented));

        /// <summary>Every file below <paramref name="root"/> with its bytes, to prove a refused merge changed nothing.</summary>
        public static string Snapshot(string root) =>
            string.Join("\n", Directory.GetFiles(root, "*", SearchOption.AllDirectories).OrderBy(p => p, StringComparer.Ordinal)
                .Select(p => p.Substring(root.Length) + " " + Convert.ToBase64String(File.ReadAllBytes(p))));
    }
}
