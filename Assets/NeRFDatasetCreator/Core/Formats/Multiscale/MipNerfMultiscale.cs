using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// mip-NeRF's multi-scale Blender layout, each rule from its readers' code (sources and lines:
    /// Documentation~/maintainers/layouts-multiscale-hdr.md):
    /// <list type="bullet">
    /// <item>One <c>metadata.json</c> in the data folder with a key per split (<c>train</c>, <c>val</c>, <c>test</c>), each
    /// holding parallel lists <c>file_path</c>, <c>cam2world</c>, <c>width</c>, <c>height</c>, <c>focal</c>, <c>label</c>,
    /// <c>near</c>, <c>far</c>, <c>lossmult</c>, <c>pix2cam</c> (google/mipnerf convert_blender_data.py, datasets.py Multicam).
    /// Every split key is written, empty when the dataset has no such view: Mip-Splatting indexes <c>[split]</c> directly.</item>
    /// <item>Exactly <see cref="Levels"/> levels, frame-major (frame i's levels are entries 4i … 4i + 3): Tri-MipRF groups
    /// entries by <c>index % 4</c> and asserts entry 0 and entry 4 share a camera.</item>
    /// <item>Names end <c>_d0.png</c> … <c>_d3.png</c>: Mip-Splatting trains on entries ending <c>d0.png</c> only unless
    /// <c>--load_allres</c>.</item>
    /// <item><c>pix2cam</c> is K⁻¹ with the OpenGL sign flips, applied to (x + ½, y + ½, 1) (Multicam
    /// <c>_generate_rays</c>); Tri-MipRF inverts it back to fx, fy, cx, cy. Ours holds the dataset's own fx, fy, cx, cy
    /// divided by 2ʲ (exact in binary). Mip-Splatting reads <c>focal</c> only and assumes the principal point at the centre.</item>
    /// <item><c>lossmult</c> 4ʲ (pixel area at level j), <c>label</c> j, as the converter writes.</item>
    /// <item><c>near</c>/<c>far</c> are distances along rays whose camera z is −1 (pix2cam's last row), i.e. z-depth bounds.</item>
    /// </list>
    /// </summary>
    public static class MipNerfMultiscale
    {
        public const string FolderName = "mipnerf";
        public const string MetadataFileName = "metadata.json";
        public const int Levels = 4;
        public static readonly string[] Splits = { "train", "val", "test" };

        /// <summary>The file of level <paramref name="level"/> of a frame whose COLMAP name is <paramref name="flatName"/>: <c>&lt;split&gt;/&lt;stem&gt;_d&lt;level&gt;.png</c>.</summary>
        public static string FilePath(string split, string flatName, int level) =>
            split + "/" + System.IO.Path.GetFileNameWithoutExtension(flatName) + "_d" + level.ToString(CultureInfo.InvariantCulture) + ".png";

        /// <summary>
        /// pix2cam of a level: [[1/fx, 0, −cx/fx], [0, −1/fy, cy/fy], [0, 0, −1]] with the intrinsics divided by
        /// 2^<paramref name="level"/> (convert_blender_data.py builds the same matrix with cx = width/2).
        /// </summary>
        public static double[][] Pix2Cam(CameraIntrinsics k, int level)
        {
            var scale = 1 << level;
            double fx = k.FlX / scale, fy = k.FlY / scale, cx = k.Cx / scale, cy = k.Cy / scale;
            return new[]
            {
                new[] { 1 / fx, 0.0, -cx / fx },
                new[] { 0.0, -1 / fy, cy / fy },
                new[] { 0.0, 0.0, -1.0 },
            };
        }

        /// <summary>
        /// z-depth bounds of a sphere of <paramref name="radius"/> about <paramref name="centre"/> seen from
        /// <paramref name="cameraToWorld"/>: its centre's depth ∓ the radius, the near bound kept above a thousandth of the far
        /// (a camera inside the sphere: an inside-out capture).
        /// </summary>
        public static (double Near, double Far) Bounds(Matrix4x4d cameraToWorld, Vector3d centre, double radius)
        {
            var toCentre = centre - cameraToWorld.Translation;
            var depth = Vector3d.Dot(toCentre, -cameraToWorld.Column(2));
            var far = Math.Max(depth + radius, radius);
            return (Math.Max(depth - radius, far * 1e-3), far);
        }

        /// <summary>One split's entry of metadata.json: <paramref name="frames"/> in order, each with its <see cref="Levels"/> levels.</summary>
        public static JObject Split(IReadOnlyList<(string FlatName, ExportFrame Frame)> frames, string split, CameraIntrinsics k, Func<ExportFrame, (double Near, double Far)> bounds)
        {
            var filePath = new JArray();
            var cam2World = new JArray();
            var width = new JArray();
            var height = new JArray();
            var focal = new JArray();
            var label = new JArray();
            var near = new JArray();
            var far = new JArray();
            var lossMult = new JArray();
            var pix2Cam = new JArray();
            foreach (var (name, frame) in frames)
            {
                var (n, f) = bounds(frame);
                for (var level = 0; level < Levels; level++)
                {
                    var factor = 1 << level;
                    filePath.Add(FilePath(split, name, level));
                    cam2World.Add(Rows(frame.CameraToWorld.ToRows()));
                    width.Add(PremultipliedBox.Reduced(k.Width, factor));
                    height.Add(PremultipliedBox.Reduced(k.Height, factor));
                    focal.Add(k.FlX / factor);
                    label.Add(level);
                    near.Add(n);
                    far.Add(f);
                    lossMult.Add((double)(factor * factor));
                    pix2Cam.Add(Rows(Pix2Cam(k, level)));
                }
            }
            return new JObject
            {
                ["file_path"] = filePath,
                ["cam2world"] = cam2World,
                ["width"] = width,
                ["height"] = height,
                ["focal"] = focal,
                ["label"] = label,
                ["near"] = near,
                ["far"] = far,
                ["lossmult"] = lossMult,
                ["pix2cam"] = pix2Cam,
            };
        }

        static JArray Rows(double[][] rows) => new JArray(rows.Select(r => new JArray(r.Select(v => (object)v).ToArray())).ToArray<object>());
    }
}
