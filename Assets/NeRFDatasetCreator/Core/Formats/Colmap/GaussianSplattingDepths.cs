using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Ground-truth depth in the layout 3D Gaussian Splatting's <c>-d/--depths</c> option reads for a COLMAP source
    /// (graphdeco-inria/gaussian-splatting at 54c035f):
    /// <list type="bullet">
    /// <item><c>&lt;source&gt;/&lt;depths&gt;/&lt;image name without its extension&gt;.png</c> (scene/dataset_readers.py:100, 110, 197),
    /// a 16-bit PNG read as <c>invdepth = value / 2^16</c> (utils/camera_utils.py:28);</item>
    /// <item><c>sparse/0/depth_params.json</c> (dataset_readers.py:157–170): per image stem a <c>scale</c> and
    /// <c>offset</c>; when scale &gt; 0 the map becomes <c>invdepth·scale + offset</c> (scene/cameras.py:73–74), and an
    /// image whose scale is below 0.2× or above 5× the median of the positive scales is marked unreliable and its depth
    /// loss masked out (cameras.py:68–71, train.py:130).</item>
    /// </list>
    /// The map must equal what the rasterizer renders, Σ (1/z)·α·T with z the view-space depth
    /// (diff-gaussian-rasterization cuda_rasterizer/forward.cu), i.e. inverse <b>z-depth</b> in 1/output units —
    /// which our depth PNGs hold as z (<see cref="ExportFrame.DepthPath"/>). Monocular estimators need a per-image fit;
    /// exact depth needs none, so every image gets the same scale <see cref="ScaleFor"/> (1 unless a surface is nearer
    /// than 65536/65535 output units) and offset 0, and passes the reliability test. A pixel without a surface is 0
    /// (inverse depth of infinity: nothing there), which is what the rasterizer renders where there are no Gaussians.
    /// An image without a depth file gets an all-zero map with scale 0, which 3DGS marks unreliable, so only its
    /// depth loss is skipped.
    /// </summary>
    public static class GaussianSplattingDepths
    {
        public const string FolderName = "depths";
        public const string ParamsFileName = "depth_params.json";

        /// <summary>3DGS divides a COLMAP depth PNG by 2^16 (camera_utils.py:28).</summary>
        public const double PngDivisor = 65536;

        /// <summary>What 3DGS trains against for a PNG value and its image's params (camera_utils.py:28, cameras.py:65, 73–74).</summary>
        public static double InverseDepth3dgs(int pngValue, double scale, double offset)
        {
            var invdepth = Math.Max(0, pngValue / PngDivisor);
            return scale > 0 ? invdepth * scale + offset : invdepth;
        }

        /// <summary>
        /// The PNG value for a z-depth in output units under <paramref name="scale"/>: round(2^16 / (z·scale)),
        /// 0 for no surface (z = 0), at most 65535.
        /// </summary>
        public static ushort Encode(double z, double scale)
        {
            if (!(z > 0)) return 0;
            var v = Math.Round(PngDivisor / (z * scale));
            return (ushort)Math.Min(ushort.MaxValue, Math.Max(1, v));
        }

        /// <summary>
        /// The shared scale: 1 when the nearest surface z ≥ 65536/65535 output units (its inverse fits in 16 bits),
        /// otherwise the smallest power of two that makes it fit (exact in binary, so scale·value/2^16 loses nothing).
        /// </summary>
        public static double ScaleFor(double nearestDepth)
        {
            var scale = 1.0;
            while (nearestDepth > 0 && PngDivisor / (nearestDepth * scale) > ushort.MaxValue) scale *= 2;
            return scale;
        }

        /// <summary>3DGS's key for an image: its name without the last extension (dataset_readers.py:100, 104).</summary>
        public static string Stem(string imageName)
        {
            var dot = imageName.LastIndexOf('.');
            return dot > 0 ? imageName.Substring(0, dot) : imageName;
        }

        /// <summary>The files <see cref="Write"/> creates for these COLMAP image names, depth maps first.</summary>
        public static IReadOnlyList<string> Destinations(string outDir, IReadOnlyList<string> names) =>
            names.Select(n => Path.Combine(outDir, FolderName, Stem(n) + ".png"))
                .Concat(new[] { Path.Combine(outDir, "sparse", "0", ParamsFileName) }).ToList();

        /// <summary>Why these frames cannot get 3DGS depth maps; empty when they can.</summary>
        public static IReadOnlyList<ValidationProblem> Check(IReadOnlyList<ExportFrame> frames, IReadOnlyList<string> names)
        {
            var problems = new List<ValidationProblem>();
            if (!frames.Any(f => f.DepthPath != null))
                problems.Add(new ValidationProblem("--depths", "no depth", "the dataset has no 16-bit depth PNGs (<image>_depth_0000.png) to export.",
                    "Capture with depth \"png\" (or \"png+exr\") in at least the train split, or convert without --depths."));
            // Names are unique (ColmapTextWriter.ImageNames); stems may still collide (r_0.png and r_0.jpg).
            foreach (var dup in names.GroupBy(Stem).Where(g => g.Count() > 1))
                problems.Add(new ValidationProblem("file_path", string.Join(", ", dup), "share the stem " + dup.Key + ", and 3DGS names depth maps and depth_params keys by stem.",
                    "Give the images distinct names before the extension."));
            // A depth file that is there but unusable is refused, never exported as an all-zero map: the user asked for depth.
            foreach (var frame in frames.Where(f => f.UnusableDepth != null))
                problems.Add(new ValidationProblem("depth", frame.UnusableDepth.Value,
                    frame.UnusableDepth.Reason + "; --depths exports only this plugin's 16-bit depth maps and refuses any other rather than write a wrong or empty map.",
                    "Re-capture the depth with this plugin, or delete the file: an image without a depth file gets an all-zero map that 3DGS marks unreliable."));
            return problems;
        }

        /// <summary>What the first pass over the depth maps found: the nearest surface (in PNG steps) and the clamped pixels.</summary>
        public sealed class DepthScan
        {
            internal int NearestStep = int.MaxValue;
            internal int Saturated;
        }

        /// <summary>
        /// Decodes every frame's depth map once before anything is written: the nearest surface sets the shared scale.
        /// Each map that cannot be decoded (truncated data, a corrupt stream, unreadable) is added to
        /// <paramref name="problems"/>, naming the file, so all of them are reported together.
        /// </summary>
        public static DepthScan Scan(ExportScene scene, ICollection<ValidationProblem> problems)
        {
            var scan = new DepthScan();
            foreach (var f in scene.Frames.Where(f => f.DepthPath != null))
            {
                var path = Path.Combine(scene.RootDirectory, f.DepthPath);
                try
                {
                    foreach (var v in PngGray16Reader.Read(path, out _, out _))
                    {
                        if (v > 0 && v < scan.NearestStep) scan.NearestStep = v;
                        if (v == ushort.MaxValue) scan.Saturated++;
                    }
                }
                catch (InvalidParameterException e)
                {
                    foreach (var p in e.Problems) problems.Add(p);
                }
                catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
                {
                    problems.Add(new ValidationProblem("depth", path, "cannot be read: " + e.Message, "Check the file and its permissions."));
                }
            }
            return scan;
        }

        /// <summary>
        /// Writes <c>depths/&lt;stem&gt;.png</c> for every frame and <c>sparse/0/depth_params.json</c> under
        /// <paramref name="outDir"/> (staged with the rest of the convert, never overwriting), reading each frame's depth PNG from the scene.
        /// </summary>
        public static void Write(ExportScene scene, IReadOnlyList<string> names, string outDir, ICollection<ValidationProblem> warnings, StagedOutput staged, DepthScan scan = null)
        {
            var unit = scene.DepthUnitScale;
            // Pass 1 (Scan): the nearest surface of the whole dataset sets the one shared scale.
            if (scan == null)
            {
                var problems = new List<ValidationProblem>();
                scan = Scan(scene, problems);
                InvalidParameterException.ThrowIfAny(problems.ToArray());
            }
            var nearestStep = scan.NearestStep;
            var saturated = scan.Saturated;
            var scale = nearestStep == int.MaxValue ? 1 : ScaleFor(nearestStep * unit);

            var folder = Path.Combine(outDir, FolderName);
            var parameters = new JObject();
            var missing = new List<string>();
            for (var i = 0; i < scene.Frames.Count; i++)
            {
                var frame = scene.Frames[i];
                ushort[] encoded;
                int width, height;
                if (frame.DepthPath == null)
                {
                    width = scene.Intrinsics.Width;
                    height = scene.Intrinsics.Height;
                    encoded = new ushort[width * height];
                    missing.Add(frame.ImagePath);
                }
                else
                {
                    var steps = PngGray16Reader.Read(Path.Combine(scene.RootDirectory, frame.DepthPath), out width, out height);
                    encoded = new ushort[steps.Length];
                    for (var p = 0; p < steps.Length; p++) encoded[p] = Encode(steps[p] * unit, scale);
                }
                staged.WriteNewBytes(Path.Combine(folder, Stem(names[i]) + ".png"), PngWriter.EncodeGray16(encoded, width, height));
                parameters[Stem(names[i])] = new JObject { ["scale"] = frame.DepthPath == null ? 0.0 : scale, ["offset"] = 0.0 };
            }
            var paramsPath = Path.Combine(outDir, "sparse", "0", ParamsFileName);
            staged.WriteNewText(paramsPath, ExportJson.Serialise(parameters));

            if (missing.Count > 0)
                warnings.Add(new ValidationProblem(ParamsFileName, missing.Count + " of " + scene.Frames.Count + " images",
                    "have no depth (e.g. " + missing[0] + "): they get an all-zero map with scale 0, which 3DGS marks unreliable (scene/cameras.py:68–71), so only their depth loss is skipped.",
                    "Capture depth in every split for depth supervision on all images."));
            if (scale != 1)
                warnings.Add(new ValidationProblem(ParamsFileName + ": scale", ValidationProblem.Format(scale),
                    "a surface is nearer than 65536/65535 output units, so the inverse depths are stored divided by " + ValidationProblem.Format(scale) + " (same scale for every image, offset 0; 3DGS multiplies it back).",
                    "Nothing to do; a nerf_synthetic-like scale (cameras at radius 4) keeps it 1."));
            if (saturated > 0)
                warnings.Add(new ValidationProblem("depth", saturated + " pixels",
                    "hold the 16-bit depth PNG's largest value (65.535 output units, clamped at capture), so their inverse depth is only an upper bound.",
                    "Use a normalisation that keeps the scene within 65 output units (e.g. nerf-synthetic)."));
        }
    }
}
