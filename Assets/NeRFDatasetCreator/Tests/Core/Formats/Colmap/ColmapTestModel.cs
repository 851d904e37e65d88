using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A COLMAP sparse model read the way scripts/python/read_write_model.py reads it (colmap/colmap at 09e7fa9:
    /// read_cameras_text/binary, read_images_text/binary, read_points3D_text, read_points3d_binary): written here from
    /// that description, independent of Core's writers, so that the tests read what a trainer reads.
    /// </summary>
    sealed class ColmapTestModel
    {
        public sealed class Camera
        {
            public int Id, ModelId, Width, Height;
            public string Model;
            public double[] Params;
        }

        public sealed class Image
        {
            public int Id, CameraId;
            public double QW, QX, QY, QZ, TX, TY, TZ;
            public string Name;
            public double[] Xs, Ys;
            public long[] PointIds;
        }

        public sealed class Point
        {
            public long Id;
            public double X, Y, Z, Error;
            public byte R, G, B;
            public int[] ImageIds, Point2DIndices;
        }

        public readonly Dictionary<int, Camera> Cameras = new Dictionary<int, Camera>();
        public readonly List<Image> Images = new List<Image>();
        public readonly List<Point> Points = new List<Point>();

        // COLMAP's model ids and parameter counts (src/colmap/sensor/models.h: SIMPLE_PINHOLE 0, PINHOLE 1, SIMPLE_RADIAL 2,
        // RADIAL 3, OPENCV 4, OPENCV_FISHEYE 5, FULL_OPENCV 6).
        static readonly string[] ModelNames = { "SIMPLE_PINHOLE", "PINHOLE", "SIMPLE_RADIAL", "RADIAL", "OPENCV", "OPENCV_FISHEYE", "FULL_OPENCV" };
        static readonly int[] ParamCounts = { 3, 4, 4, 5, 8, 8, 12 };

        public static ColmapTestModel ReadText(string folder)
        {
            var model = new ColmapTestModel();
            foreach (var e in DataLines(Path.Combine(folder, "cameras.txt")))
                model.Cameras[int.Parse(e[0], CultureInfo.InvariantCulture)] = new Camera
                {
                    Id = int.Parse(e[0], CultureInfo.InvariantCulture), Model = e[1], ModelId = Array.IndexOf(ModelNames, e[1]),
                    Width = int.Parse(e[2], CultureInfo.InvariantCulture), Height = int.Parse(e[3], CultureInfo.InvariantCulture),
                    Params = e.Skip(4).Select(D).ToArray(),
                };
            var lines = File.ReadAllText(Path.Combine(folder, "images.txt")).Split('\n');
            for (var i = 0; i < lines.Length; i++)
            {
                var line = lines[i].Trim();
                if (line.Length == 0 || line[0] == '#') continue;
                var e = line.Split(' ');
                var p = lines[++i].Split(new[] { ' ' }, StringSplitOptions.RemoveEmptyEntries); // the POINTS2D line always follows
                var n = p.Length / 3;
                model.Images.Add(new Image
                {
                    Id = int.Parse(e[0], CultureInfo.InvariantCulture), QW = D(e[1]), QX = D(e[2]), QY = D(e[3]), QZ = D(e[4]),
                    TX = D(e[5]), TY = D(e[6]), TZ = D(e[7]), CameraId = int.Parse(e[8], CultureInfo.InvariantCulture), Name = e[9],
                    Xs = Enumerable.Range(0, n).Select(k => D(p[3 * k])).ToArray(),
                    Ys = Enumerable.Range(0, n).Select(k => D(p[3 * k + 1])).ToArray(),
                    PointIds = Enumerable.Range(0, n).Select(k => long.Parse(p[3 * k + 2], CultureInfo.InvariantCulture)).ToArray(),
                });
            }
            foreach (var e in DataLines(Path.Combine(folder, "points3D.txt")))
            {
                var track = e.Skip(8).Select(s => int.Parse(s, CultureInfo.InvariantCulture)).ToArray();
                model.Points.Add(new Point
                {
                    Id = long.Parse(e[0], CultureInfo.InvariantCulture), X = D(e[1]), Y = D(e[2]), Z = D(e[3]),
                    R = byte.Parse(e[4], CultureInfo.InvariantCulture), G = byte.Parse(e[5], CultureInfo.InvariantCulture), B = byte.Parse(e[6], CultureInfo.InvariantCulture),
                    Error = D(e[7]),
                    ImageIds = track.Where((_, k) => k % 2 == 0).ToArray(),
                    Point2DIndices = track.Where((_, k) => k % 2 == 1).ToArray(),
                });
            }
            return model;
        }

        public static ColmapTestModel ReadBinary(string folder)
        {
            var model = new ColmapTestModel();
            using (var r = new BinaryReader(File.OpenRead(Path.Combine(folder, "cameras.bin"))))
            {
                var count = r.ReadUInt64();
                for (ulong c = 0; c < count; c++)
                {
                    var camera = new Camera { Id = (int)r.ReadUInt32(), ModelId = r.ReadInt32(), Width = (int)r.ReadUInt64(), Height = (int)r.ReadUInt64() };
                    camera.Model = ModelNames[camera.ModelId];
                    camera.Params = Enumerable.Range(0, ParamCounts[camera.ModelId]).Select(_ => r.ReadDouble()).ToArray();
                    model.Cameras[camera.Id] = camera;
                }
                AssertEnd(r, "cameras.bin");
            }
            using (var r = new BinaryReader(File.OpenRead(Path.Combine(folder, "images.bin"))))
            {
                var count = r.ReadUInt64();
                for (ulong i = 0; i < count; i++)
                {
                    var image = new Image
                    {
                        Id = (int)r.ReadUInt32(), QW = r.ReadDouble(), QX = r.ReadDouble(), QY = r.ReadDouble(), QZ = r.ReadDouble(),
                        TX = r.ReadDouble(), TY = r.ReadDouble(), TZ = r.ReadDouble(), CameraId = (int)r.ReadUInt32(),
                    };
                    var name = new List<byte>();
                    for (var b = r.ReadByte(); b != 0; b = r.ReadByte()) name.Add(b);
                    image.Name = Encoding.UTF8.GetString(name.ToArray());
                    var n = (int)r.ReadUInt64();
                    image.Xs = new double[n]; image.Ys = new double[n]; image.PointIds = new long[n];
                    for (var k = 0; k < n; k++)
                    {
                        image.Xs[k] = r.ReadDouble();
                        image.Ys[k] = r.ReadDouble();
                        image.PointIds[k] = (long)r.ReadUInt64();
                    }
                    model.Images.Add(image);
                }
                AssertEnd(r, "images.bin");
            }
            using (var r = new BinaryReader(File.OpenRead(Path.Combine(folder, "points3D.bin"))))
            {
                var count = r.ReadUInt64();
                for (ulong i = 0; i < count; i++)
                {
                    var point = new Point
                    {
                        Id = (long)r.ReadUInt64(), X = r.ReadDouble(), Y = r.ReadDouble(), Z = r.ReadDouble(),
                        R = r.ReadByte(), G = r.ReadByte(), B = r.ReadByte(), Error = r.ReadDouble(),
                    };
                    var length = (int)r.ReadUInt64();
                    point.ImageIds = new int[length];
                    point.Point2DIndices = new int[length];
                    for (var e = 0; e < length; e++)
                    {
                        point.ImageIds[e] = (int)r.ReadUInt32();
                        point.Point2DIndices[e] = (int)r.ReadUInt32();
                    }
                    model.Points.Add(point);
                }
                AssertEnd(r, "points3D.bin");
            }
            return model;
        }

        /// <summary>
        /// COLMAP's PINHOLE projection of world point P into <paramref name="image"/>, derived here: X_cam = q·P·q* + t
        /// with q = (w, u) unit, q·P·q* = P + 2w(u × P) + 2u × (u × P); then x = fx·X/Z + cx, y = fy·Y/Z + cy, pixel
        /// centres at i + 0.5 (colmap doc/cameras.rst). Returns the camera-frame Z.
        /// </summary>
        public double Project(Image image, double px, double py, double pz, out double x, out double y)
        {
            var p = new Vector3d(px, py, pz);
            var u = new Vector3d(image.QX, image.QY, image.QZ);
            var uxp = Vector3d.Cross(u, p);
            var rotated = p + 2 * image.QW * uxp + 2 * Vector3d.Cross(u, uxp);
            var c = rotated + new Vector3d(image.TX, image.TY, image.TZ);
            var k = Cameras[image.CameraId].Params;
            x = k[0] * c.X / c.Z + k[2];
            y = k[1] * c.Y / c.Z + k[3];
            return c.Z;
        }

        /// <summary>The camera centre −Rᵀt: t rotated by q* and negated.</summary>
        public static Vector3d Centre(Image image)
        {
            var u = new Vector3d(-image.QX, -image.QY, -image.QZ);
            var t = new Vector3d(image.TX, image.TY, image.TZ);
            var uxt = Vector3d.Cross(u, t);
            return -(t + 2 * image.QW * uxt + 2 * Vector3d.Cross(u, uxt));
        }

        static void AssertEnd(BinaryReader r, string file)
        {
            if (r.BaseStream.Position != r.BaseStream.Length) throw new InvalidDataException(file + " has " + (r.BaseStream.Length - r.BaseStream.Position) + " bytes after its last record.");
        }

        static IEnumerable<string[]> DataLines(string path) => File.ReadAllLines(path)
            .Select(l => l.Trim()).Where(l => l.Length > 0 && l[0] != '#').Select(l => l.Split(' '));

        static double D(string s) => double.Parse(s, NumberStyles.Float, CultureInfo.InvariantCulture);
    }
}
