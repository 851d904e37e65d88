using System;
using System.Globalization;
using System.IO;
using System.Security.Cryptography;
using System.Text;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The <c>pointCloud</c> record of <c>dataset_config.json</c>: which file holds the target's surface points, how
    /// many, and the file's SHA-256. 3DGS writes its random ±1.3 cube into a Blender dataset under the same name
    /// <c>points3d.ply</c> when it finds none (scene/dataset_readers.py, readNerfSyntheticInfo), so the name alone
    /// proves nothing: only a file whose hash matches this record is the plugin's cloud (<see cref="PointCloudOwnership"/>).
    /// </summary>
    public sealed class PointCloudRecord
    {
        public const string Key = "pointCloud";

        public PointCloudRecord(string file, string sha256, int points)
        {
            File = file ?? throw new ArgumentNullException(nameof(file));
            Sha256 = sha256 ?? throw new ArgumentNullException(nameof(sha256));
            Points = points;
        }

        /// <summary>Dataset-relative path, <c>points3d.ply</c>.</summary>
        public string File { get; }

        /// <summary>Lower-case hex SHA-256 of the whole file.</summary>
        public string Sha256 { get; }

        public int Points { get; }

        /// <summary>The record of a cloud just written at <paramref name="path"/>, stored under <paramref name="relativePath"/>.</summary>
        public static PointCloudRecord Of(string path, string relativePath, int points) => new PointCloudRecord(relativePath, HashOf(path), points);

        public static string HashOf(string path)
        {
            using (var sha = SHA256.Create())
            using (var stream = ReadableFile.OpenRead(path, long.MaxValue)) // streamed: any size, but a pipe or device is refused unopened
            {
                var hash = sha.ComputeHash(stream);
                var hex = new StringBuilder(hash.Length * 2);
                foreach (var b in hash) hex.Append(b.ToString("x2", CultureInfo.InvariantCulture));
                return hex.ToString();
            }
        }

        public JObject ToJson() => new JObject
        {
            ["file"] = File,
            ["points"] = Points,
            ["sha256"] = Sha256,
            ["meaning"] = "the target's surface points sampled by " + PluginInfo.Name + "; any other file under this name (e.g. 3DGS's random cloud) is not the target",
        };

        /// <summary>The record in a parsed dataset_config.json, or null when there is none or it is malformed.</summary>
        public static PointCloudRecord FromConfig(JObject config)
        {
            if (!(config?[Key] is JObject o)) return null;
            var file = o["file"];
            var sha = o["sha256"];
            var points = o["points"];
            // A count beyond int (3e9, or 30 digits) is a malformed record like any other, not an OverflowException.
            if (file?.Type != JTokenType.String || sha?.Type != JTokenType.String || !JsonValues.TryInt(points, out var count) || count < 0) return null;
            return new PointCloudRecord((string)file, ((string)sha).ToLowerInvariant(), count);
        }
    }
}
