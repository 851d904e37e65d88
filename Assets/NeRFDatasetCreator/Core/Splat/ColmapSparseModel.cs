using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What gsplat's COLMAP parser takes from a sparse model to normalise the world: every image's cam_from_world
    /// (OpenCV axes) and every 3D point's xyz. Binary when cameras.bin, images.bin and points3D.bin are all there, else
    /// text — pycolmap's rule (Reconstruction::Read; see maintainers/exports.md). Layouts as COLMAP's read_write_model.py.
    /// </summary>
    public sealed class ColmapSparseModel
    {
        ColmapSparseModel(List<ColmapPose> poses, List<Vector3d> points, string source)
        {
            Poses = poses;
            Points = points;
            Source = source;
        }

        public IReadOnlyList<ColmapPose> Poses { get; }

        /// <summary>The points' xyz (gsplat casts them to float32: <see cref="GsplatNormalisation"/> does too).</summary>
        public IReadOnlyList<Vector3d> Points { get; }

        /// <summary>The folder read and which files ("binary" or "text").</summary>
        public string Source { get; }

        /// <summary>gsplat's folder rule: <c>data_dir/sparse/0/</c>, else <c>data_dir/sparse</c> (colmap.py lines 137–139); null when neither exists.</summary>
        public static string FolderOf(string dataDir)
        {
            var zero = Path.Combine(dataDir, "sparse", "0");
            if (Directory.Exists(zero)) return zero;
            var sparse = Path.Combine(dataDir, "sparse");
            return Directory.Exists(sparse) ? sparse : null;
        }

        public static ColmapSparseModel Read(string folder)
        {
            var binary = File.Exists(Path.Combine(folder, "cameras.bin")) && File.Exists(Path.Combine(folder, "images.bin")) && File.Exists(Path.Combine(folder, "points3D.bin"));
            try
            {
                return binary
                    ? new ColmapSparseModel(ImagesBinary(Path.Combine(folder, "images.bin")), PointsBinary(Path.Combine(folder, "points3D.bin")), folder + " (binary)")
                    : new ColmapSparseModel(ImagesText(Path.Combine(folder, "images.txt")), PointsText(Path.Combine(folder, "points3D.txt")), folder + " (text)");
            }
            catch (Exception e) when (e is EndOfStreamException || e is FormatException || e is OverflowException)
            {
                throw TrainedModel.Refuse("data_dir", folder, "holds a COLMAP model that cannot be read: " + e.Message, "Restore the COLMAP model gsplat trained on (convert --to colmap writes it).");
            }
        }

        static List<ColmapPose> ImagesText(string path)
        {
            var poses = new List<ColmapPose>();
            var lines = FileOps.ReadText(path).Split('\n');
            var expectPose = true;
            foreach (var raw in lines)
            {
                var line = raw.Trim();
                if (line.StartsWith("#", StringComparison.Ordinal)) continue;
                if (!expectPose) { expectPose = true; continue; } // the POINTS2D line, possibly empty
                if (line.Length == 0) continue;
                var f = line.Split((char[])null, StringSplitOptions.RemoveEmptyEntries);
                if (f.Length < 10) throw new FormatException(path + ": an image line has " + f.Length + " fields, not 10.");
                poses.Add(new ColmapPose(new Quaterniond(D(f[2]), D(f[3]), D(f[4]), D(f[1])), new Vector3d(D(f[5]), D(f[6]), D(f[7]))));
                expectPose = false;
            }
            return poses;
        }

        static List<Vector3d> PointsText(string path)
        {
            var points = new List<Vector3d>();
            foreach (var raw in FileOps.ReadText(path).Split('\n'))
            {
                var line = raw.Trim();
                if (line.Length == 0 || line.StartsWith("#", StringComparison.Ordinal)) continue;
                var f = line.Split((char[])null, StringSplitOptions.RemoveEmptyEntries);
                if (f.Length < 8) throw new FormatException(path + ": a point line has " + f.Length + " fields, not at least 8.");
                points.Add(new Vector3d(D(f[1]), D(f[2]), D(f[3])));
            }
            return points;
        }

        static List<ColmapPose> ImagesBinary(string path)
        {
            var poses = new List<ColmapPose>();
            using (var r = new BinaryReader(ReadableFile.OpenRead(path, FileOps.MaxTextBytes)))
            {
                var count = r.ReadUInt64();
                for (ulong i = 0; i < count; i++)
                {
                    r.ReadUInt32();
                    double qw = r.ReadDouble(), qx = r.ReadDouble(), qy = r.ReadDouble(), qz = r.ReadDouble();
                    double tx = r.ReadDouble(), ty = r.ReadDouble(), tz = r.ReadDouble();
                    r.ReadUInt32();
                    while (r.ReadByte() != 0) { }
                    var points2D = r.ReadUInt64();
                    Skip(r, points2D, 24, path);
                    poses.Add(new ColmapPose(new Quaterniond(qx, qy, qz, qw), new Vector3d(tx, ty, tz)));
                }
            }
            return poses;
        }

        static List<Vector3d> PointsBinary(string path)
        {
            var points = new List<Vector3d>();
            using (var r = new BinaryReader(ReadableFile.OpenRead(path, FileOps.MaxTextBytes)))
            {
                var count = r.ReadUInt64();
                for (ulong i = 0; i < count; i++)
                {
                    r.ReadUInt64();
                    points.Add(new Vector3d(r.ReadDouble(), r.ReadDouble(), r.ReadDouble()));
                    r.ReadBytes(3);
                    r.ReadDouble();
                    var track = r.ReadUInt64();
                    Skip(r, track, 8, path);
                }
            }
            return points;
        }

        /// <summary>Reads past <paramref name="count"/> records of <paramref name="size"/> bytes (the file stream is read-only forward).</summary>
        static void Skip(BinaryReader r, ulong count, int size, string path)
        {
            if (count > (1UL << 40) / (ulong)size) throw new FormatException(path + " declares " + count + " entries, more than any model holds.");
            var left = (long)count * size;
            var buffer = new byte[Math.Min(left, 1 << 16)];
            while (left > 0)
            {
                var read = r.Read(buffer, 0, (int)Math.Min(left, buffer.Length));
                if (read <= 0) throw new EndOfStreamException(path + " ends inside its records.");
                left -= read;
            }
        }

        static double D(string s) => double.Parse(s, NumberStyles.Float, CultureInfo.InvariantCulture);
    }
}
