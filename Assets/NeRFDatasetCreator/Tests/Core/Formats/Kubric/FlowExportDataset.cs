using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// The analytic dynamic dataset the flow layouts are tested on (as FlowWriterTests makes it): the geometry pack every
    /// step, depth PNG + EXR, flow/ written by <see cref="FlowWriter.Write"/>. Only the opaque sphere moves (0.4 along +X).
    /// </summary>
    static class FlowExportDataset
    {
        public const int Width = 64, Height = 48;

        public static string Write(string parent, string name, bool monocular, FlowSettings settings = null)
        {
            var folder = AnalyticDataset.Write(parent, name, new AnalyticDataset.Options
            {
                Width = Width, Height = Height, Supersampling = 1, Train = monocular ? 5 : 2, Val = 1, Test = 1,
                TimeSteps = monocular ? 5 : 3, Monocular = monocular, PointCloud = 0,
                MeshesAt = AnalyticSceneMeshes.At, GeometryPackEveryStep = true,
                Configure = s => { foreach (var split in new[] { s.Train, s.Val, s.Test }) split.Depth = ExtraOutput.PngAndExr; },
            });
            FlowWriter.Write(folder, settings ?? new FlowSettings { On = true });
            return folder;
        }

        /// <summary>The dataset's c2w of <paramref name="image"/> as NeRF reads transforms_*.json.</summary>
        public static Matrix4x4d Pose(string dataset, string image)
        {
            foreach (var split in new[] { "train", "val", "test" })
            {
                var json = JObject.Parse(File.ReadAllText(Path.Combine(dataset, "transforms_" + split + ".json")));
                foreach (var frame in (JArray)json["frames"])
                {
                    var path = ((string)frame["file_path"]).TrimStart('.', '/');
                    if (path == image || path + ".png" == image)
                        return Matrix4x4d.FromRows(((JArray)frame["transform_matrix"]).Select(r => r.Select(x => (double)x).ToArray()).ToArray());
                }
            }
            throw new FileNotFoundException(image + " is in no transforms file");
        }

        /// <summary>The focal length in pixels from camera_angle_x (NeRF's load_blender).</summary>
        public static double Focal(string dataset)
        {
            var json = JObject.Parse(File.ReadAllText(Path.Combine(dataset, "transforms_train.json")));
            return 0.5 * Width / System.Math.Tan(0.5 * (double)json["camera_angle_x"]);
        }

        /// <summary>
        /// The pixel a static point seen at pixel (u, v) of view a lands on in view b — from the depth EXR (z along the
        /// camera axis) and the two poses, NeRF's get_rays convention with pixel centres at u + 0.5 — as (x, y) continuous,
        /// or null where the depth map has no surface.
        /// </summary>
        public static (double X, double Y)? StaticLanding(string dataset, string depthExr, Matrix4x4d a, Matrix4x4d b, double f, int u, int v)
        {
            var depth = ExrReader.Read(Path.Combine(dataset, depthExr));
            return StaticLanding(depth, a, b, f, u, v);
        }

        public static (double X, double Y)? StaticLanding(ExrImage depth, Matrix4x4d a, Matrix4x4d b, double f, int u, int v)
        {
            var z = depth.Channel("Y")[v * Width + u];
            if (!(z > 0) || float.IsInfinity(z)) return null;
            double cx = (u + 0.5 - Width / 2.0) / f * z, cy = -(v + 0.5 - Height / 2.0) / f * z, cz = -z;
            var world = a.MultiplyPoint(new Vector3d(cx, cy, cz));
            var inB = b.InverseRigid().MultiplyPoint(world);
            return (f * inB.X / -inB.Z + Width / 2.0, -f * inB.Y / -inB.Z + Height / 2.0);
        }

        /// <summary>Frame <paramref name="image"/>'s depth EXR beside it (train/r_3.png → train/r_3_depth_0000.exr).</summary>
        public static string DepthExr(string image) => image.Substring(0, image.Length - 4) + "_depth_0000.exr";
    }
}
