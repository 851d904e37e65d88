using System;
using System.IO;
using System.Text;

namespace NerfDatasetCreator
{
    /// <summary>
    /// COLMAP's binary model, byte for byte as COLMAP writes it (src/colmap/scene/reconstruction_io_binary.cc at
    /// 5d968cf: <c>WriteCamerasBinary</c> lines 340–356, <c>WriteImagesBinary</c> 408–440, <c>WritePoints3DBinary</c>
    /// 449–474; the same layout as scripts/python/read_write_model.py's <c>write_*_binary</c>), all little-endian:
    /// <code>
    /// cameras.bin   u64 count; per camera: u32 camera_id, i32 model_id (PINHOLE = 1), u64 width, u64 height, f64 params[4] (fx fy cx cy)
    /// images.bin    u64 count; per image:  u32 image_id, f64 qw qx qy qz, f64 tx ty tz, u32 camera_id, name bytes + '\0',
    ///                                      u64 num_points2D, per point: f64 x, f64 y, u64 point3D_id
    /// points3D.bin  u64 count; per point:  u64 point3D_id, f64 x y z, u8 r g b, f64 error,
    ///                                      u64 track_length, per element: u32 image_id, u32 point2D_idx
    /// </code>
    /// (camera_t, image_t, point2D_t are uint32_t, point3D_t is uint64_t: src/colmap/util/types.h.) No rigs.bin and
    /// frames.bin: COLMAP reads a model without them as one rig per camera (reconstruction_io_binary.cc lines 176–181),
    /// and 3DGS and gsplat's readers never open them. The names are UTF-8, as COLMAP and read_write_model.py store them.
    /// </summary>
    public static class ColmapBinaryWriter
    {
        public const int PinholeModelId = 1;

        /// <summary>Each method writes one file's bytes into <paramref name="stream"/> and closes it.</summary>
        public static void WriteCameras(Stream stream, CameraIntrinsics k) => WriteCameras(stream, k, null);

        /// <summary>cameras.bin with <paramref name="lens"/>'s model id and parameters (<see cref="LensDistortion.ColmapParams"/>), or PINHOLE when it is null.</summary>
        public static void WriteCameras(Stream stream, CameraIntrinsics k, LensDistortion lens)
        {
            using (var w = Writer(stream))
            {
                w.Write((ulong)1);
                w.Write((uint)1);
                w.Write(lens == null ? PinholeModelId : lens.ColmapModelId);
                w.Write((ulong)k.Width);
                w.Write((ulong)k.Height);
                foreach (var p in lens == null ? new[] { k.FlX, k.FlY, k.Cx, k.Cy } : lens.ColmapParams(k)) w.Write(p);
            }
        }

        public static void WriteImages(Stream stream, ColmapModel model)
        {
            using (var w = Writer(stream))
            {
                w.Write((ulong)model.Names.Count);
                for (var i = 0; i < model.Names.Count; i++)
                {
                    var q = model.Poses[i].Rotation;
                    var t = model.Poses[i].Translation;
                    w.Write((uint)(i + 1));
                    w.Write(q.W); w.Write(q.X); w.Write(q.Y); w.Write(q.Z);
                    w.Write(t.X); w.Write(t.Y); w.Write(t.Z);
                    w.Write((uint)1);
                    var name = model.Names[i];
                    if (name.IndexOf('\0') >= 0) throw new ArgumentException("An image name cannot hold a NUL character: " + name);
                    w.Write(Encoding.UTF8.GetBytes(name));
                    w.Write((byte)0);
                    var observed = model.Observations[i];
                    var pose = model.Poses[i];
                    w.Write((ulong)observed.Length);
                    for (var k = 0; k < observed.Length; k++)
                    {
                        pose.Project(model.Points[observed[k]].Position, model.Camera, model.Lens, out var x, out var y);
                        w.Write(x); w.Write(y);
                        w.Write((ulong)(observed[k] + 1));
                    }
                }
            }
        }

        public static void WritePoints3D(Stream stream, ColmapModel model)
        {
            using (var w = Writer(stream))
            {
                w.Write((ulong)model.Points.Count);
                for (var p = 0; p < model.Points.Count; p++)
                {
                    var point = model.Points[p];
                    w.Write((ulong)(p + 1));
                    w.Write(point.Position.X); w.Write(point.Position.Y); w.Write(point.Position.Z);
                    w.Write(point.Red); w.Write(point.Green); w.Write(point.Blue);
                    w.Write(model.Error(p));
                    w.Write((ulong)model.TrackLength(p));
                    for (var e = model.TrackStart[p]; e < model.TrackStart[p + 1]; e++)
                    {
                        w.Write((uint)(model.TrackImage[e] + 1));
                        w.Write((uint)model.TrackPoint2D[e]);
                    }
                }
            }
        }

        // BinaryWriter is little-endian on every platform. Disposing it flushes the buffer and closes the stream.
        static BinaryWriter Writer(Stream stream) => new BinaryWriter(new BufferedStream(stream, 1 << 16), Encoding.UTF8, false);
    }
}
