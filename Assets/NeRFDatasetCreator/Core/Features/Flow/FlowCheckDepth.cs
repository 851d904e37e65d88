using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A view's z-depth in output units for the flow check (<see cref="FlowCheck"/>), and how far it may be from the
    /// surface the flow was computed on. The float EXR (<c>r_&lt;i&gt;_depth_0000.exr</c>, output units, beside the
    /// view's image) when the capture wrote it, else the 16-bit PNG its <c>depth_path</c> names (steps of
    /// <c>integer_depth_scale</c>); 0 = no surface. The dataset is this plugin's (it has <c>flow/flow.json</c>), so the
    /// EXR's name is ours to know.
    /// </summary>
    public sealed class FlowCheckDepth
    {
        /// <summary>
        /// Output units the depth may differ from the target's mesh, whatever the file: the geometry pack's facets against
        /// the rendered (or, in the analytic scene, the exact) surface — the tolerance <see cref="GeometryPackDepthCheck"/>
        /// holds the same mesh to (5 PNG steps; the analytic spheres' facets are within 3e-4 of their surface).
        /// </summary>
        public const double MeshTolerance = GeometryPackDepthCheck.Tolerance;

        FlowCheckDepth(float[] z, int width, int height, double uncertainty, string file)
        {
            Z = z;
            Width = width;
            Height = height;
            Uncertainty = uncertainty;
            File = file;
        }

        /// <summary>z-depth per pixel, rows top first, output units; 0 where no surface.</summary>
        public float[] Z { get; }
        public int Width { get; }
        public int Height { get; }

        /// <summary>How far (output units) the depth may be from the mesh's surface: <see cref="MeshTolerance"/>, plus half a step for a PNG.</summary>
        public double Uncertainty { get; }

        /// <summary>The file read, relative to the dataset.</summary>
        public string File { get; }

        /// <summary>The EXR beside <paramref name="image"/> (dataset-relative, '/'), else the view's depth PNG, else null.</summary>
        public static FlowCheckDepth Read(string root, string image, CheckView view)
        {
            var exr = ExrName(image);
            var exrPath = exr == null ? null : PathSafety.Inside(root, exr, out _);
            if (exrPath != null && System.IO.File.Exists(exrPath))
            {
                var e = ExrReader.Read(exrPath);
                var channel = e.Channel("Y") ?? e.Channel("R") ?? throw new InvalidDataException(exr + " has no Y or R channel to read depth from.");
                return new FlowCheckDepth(channel, e.Width, e.Height, MeshTolerance, exr);
            }
            if (view?.DepthFile == null) return null;
            var png = PngGray16Reader.Read(Path.Combine(root, view.DepthFile.Replace('/', Path.DirectorySeparatorChar)), out var w, out var h);
            var z = new float[png.Length];
            for (var i = 0; i < z.Length; i++) z[i] = (float)(png[i] * view.DepthScale);
            return new FlowCheckDepth(z, w, h, MeshTolerance + 0.5 * view.DepthScale, view.DepthFile);
        }

        /// <summary><c>train/r_3.png</c> → <c>train/r_3_depth_0000.exr</c> (<see cref="DatasetLayout.Suffix"/>).</summary>
        static string ExrName(string image)
        {
            if (image == null || !image.EndsWith(".png", StringComparison.OrdinalIgnoreCase)) return null;
            return image.Substring(0, image.Length - 4) + DatasetLayout.Suffix(DatasetFileKind.DepthExr);
        }

        public double At(int x, int y) => Z[y * Width + x];

        /// <summary>
        /// Bilinear depth at continuous pixel (x, y) (centres at +0.5) when the four pixels around it hold one smooth surface
        /// (all with depth, within 2 % of each other, as <see cref="MultiViewGeometryCheck"/> judges smoothness); NaN at a
        /// silhouette, a depth edge or the border, where the sample may belong to either side.
        /// </summary>
        public double Smooth(double x, double y)
        {
            double fx = x - 0.5, fy = y - 0.5;
            var x0 = (int)Math.Floor(fx);
            var y0 = (int)Math.Floor(fy);
            if (x0 < 0 || y0 < 0 || x0 + 1 >= Width || y0 + 1 >= Height) return double.NaN;
            var q = y0 * Width + x0;
            double a = Z[q], b = Z[q + 1], c = Z[q + Width], d = Z[q + Width + 1];
            double lo = Math.Min(Math.Min(a, b), Math.Min(c, d)), hi = Math.Max(Math.Max(a, b), Math.Max(c, d));
            if (!(lo > 0) || hi - lo > SmoothShare * hi + 2 * Uncertainty) return double.NaN;
            double ax = fx - x0, ay = fy - y0;
            return (a * (1 - ax) + b * ax) * (1 - ay) + (c * (1 - ax) + d * ax) * ay;
        }

        /// <summary>Neighbouring depths within this share (and twice the uncertainty) are one smooth surface.</summary>
        public const double SmoothShare = 0.02;

        /// <summary>Whether pixel (x, y) and its four neighbours are one smooth surface (a depth pixel away from silhouettes and edges).</summary>
        public bool Interior(int x, int y)
        {
            if (x < 1 || y < 1 || x + 1 >= Width || y + 1 >= Height) return false;
            var p = y * Width + x;
            double z = Z[p];
            if (!(z > 0)) return false;
            var edge = SmoothShare * z + 2 * Uncertainty;
            return Math.Abs(Z[p - 1] - z) <= edge && Math.Abs(Z[p + 1] - z) <= edge && Math.Abs(Z[p - Width] - z) <= edge && Math.Abs(Z[p + Width] - z) <= edge;
        }
    }
}
