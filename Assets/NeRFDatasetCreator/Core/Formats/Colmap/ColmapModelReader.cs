using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The cameras of a COLMAP text model (<c>cameras.txt</c>, <c>images.txt</c>), read the way COLMAP's own
    /// scripts/python/read_write_model.py does: '#' lines are comments, every image line
    /// (IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME) is followed by one line of 2D points, which is skipped even
    /// when empty. COLMAP stores world-to-camera extrinsics in OpenCV camera axes (x right, y down, looking along
    /// +z): the camera centre is −Rᵀt and the OpenGL camera-to-world matrix is [Rᵀ·diag(1, −1, −1) | −Rᵀt], the exact
    /// inverse of <see cref="ColmapTextWriter.WorldToCamera"/>. The model's world is taken as the output world: true
    /// for this plugin's exports, while a model from photographs has an arbitrary world that a placement can scale
    /// and move. Pinhole models are read as such; SIMPLE_RADIAL, RADIAL and OPENCV also, with their distortion
    /// reported as not reproduced; fisheye and other models are refused.
    /// </summary>
    public static class ColmapModelReader
    {
        /// <summary>Reads <c>cameras.txt</c> and <c>images.txt</c> from <paramref name="folder"/> (e.g. <c>sparse/0</c>).</summary>
        public static ImportedPoses ReadFolder(string folder, SceneNormalisation placement = null)
        {
            var cameras = Path.Combine(folder ?? "", "cameras.txt");
            var images = Path.Combine(folder ?? "", "images.txt");
            if (!File.Exists(cameras) || !File.Exists(images))
                throw Fail("path", folder ?? "", "has no cameras.txt and images.txt (a COLMAP text model).",
                    "Give the model folder (e.g. sparse/0); convert a binary model with `colmap model_converter --output_type TXT`.");
            return Read(ReadText(cameras), ReadText(images), folder, placement);
        }

        /// <summary>A model file's text; one that cannot be read, or is too large to be a model (FileOps.MaxTextBytes), is a problem naming it.</summary>
        static string ReadText(string path)
        {
            try { return FileOps.ReadText(path); }
            catch (FileTooLargeException e) { throw Fail("path", path, e.Reason, "Give the folder of a COLMAP text model (cameras.txt, images.txt)."); }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                throw Fail("path", path, "cannot be read: " + e.Message, "Give the folder of a COLMAP text model (cameras.txt, images.txt).");
            }
        }

        public static ImportedPoses Read(string camerasText, string imagesText, string sourceName, SceneNormalisation placement = null)
        {
            var problems = new List<ValidationProblem>();
            var warnings = new List<ValidationProblem>();
            var intrinsics = ReadCameras(camerasText, problems, warnings);
            var cameras = new List<ImportedCamera>();
            var lines = (imagesText ?? "").Replace("\r\n", "\n").Split('\n');
            for (var i = 0; i < lines.Length; i++)
            {
                var line = lines[i].Trim();
                if (line.Length == 0 || line[0] == '#') continue;
                var field = "images.txt line " + (i + 1).ToString(CultureInfo.InvariantCulture);
                i++; // the POINTS2D line that always follows an image line
                var e = line.Split((char[])null, StringSplitOptions.RemoveEmptyEntries);
                if (e.Length < 10 || !Numbers(e, 1, 7, out var v) || !int.TryParse(e[8], NumberStyles.Integer, CultureInfo.InvariantCulture, out var cameraId))
                {
                    problems.Add(new ValidationProblem(field, line, "is not IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME.", "Write the model with COLMAP's text exporter."));
                    continue;
                }
                var q = new Quaterniond(v[1], v[2], v[3], v[0]);
                if (!(Math.Abs(q.Norm - 1) < 1e-3))
                {
                    problems.Add(new ValidationProblem(field + " (QW QX QY QZ)", string.Join(" ", e.Skip(1).Take(4)), "is not a unit quaternion.", "Write the rotation as a unit quaternion."));
                    continue;
                }
                if (!intrinsics.TryGetValue(cameraId, out var k))
                {
                    problems.Add(new ValidationProblem(field + " (CAMERA_ID)", e[8], "names no camera of cameras.txt.", "Export cameras.txt and images.txt of the same model."));
                    continue;
                }
                var c2w = CameraToWorld(q.Normalized(), new Vector3d(v[4], v[5], v[6]));
                // The same checks as an imported transforms file (TransformsPoseReader): finite numbers can still give a
                // camera centre −Rᵀt beyond the largest double.
                var poseProblem = PosePlacement.Problem(c2w);
                if (poseProblem != null)
                {
                    problems.Add(new ValidationProblem(field + " (camera centre −Rᵀt)", c2w.Translation.ToString(), poseProblem,
                        "Write a model whose camera centres are finite (COLMAP's own reconstructions always are)."));
                    continue;
                }
                cameras.Add(new ImportedCamera(e[9], PosePlacement.SplitFromName(e[9]), c2w, PosePlacement.ToUnityPose(c2w, placement), k));
            }
            InvalidParameterException.ThrowIfAny(problems.ToArray());
            if (cameras.Count == 0) throw Fail(sourceName + "/images.txt", "no images", "lists no image.", "Give a model with registered images.");
            return new ImportedPoses(sourceName, "colmap", cameras, placement, warnings);
        }

        /// <summary>The OpenGL camera-to-world matrix of COLMAP's world-to-camera rotation <paramref name="q"/> and translation <paramref name="t"/>.</summary>
        public static Matrix4x4d CameraToWorld(Quaterniond q, Vector3d t)
        {
            // Row j of R is R's transpose's column j: the OpenCV camera axis j in world coordinates.
            var c0 = q.Rotate(Vector3d.UnitX);
            var c1 = q.Rotate(Vector3d.UnitY);
            var c2 = q.Rotate(Vector3d.UnitZ);
            var x = new Vector3d(c0.X, c1.X, c2.X);
            var y = new Vector3d(c0.Y, c1.Y, c2.Y);
            var z = new Vector3d(c0.Z, c1.Z, c2.Z);
            var centre = -(x * t.X + y * t.Y + z * t.Z);
            return Matrix4x4d.FromColumns(x, -y, -z, centre);
        }

        static Dictionary<int, ImportedIntrinsics> ReadCameras(string text, List<ValidationProblem> problems, List<ValidationProblem> warnings)
        {
            var result = new Dictionary<int, ImportedIntrinsics>();
            var lines = (text ?? "").Replace("\r\n", "\n").Split('\n');
            for (var i = 0; i < lines.Length; i++)
            {
                var line = lines[i].Trim();
                if (line.Length == 0 || line[0] == '#') continue;
                var field = "cameras.txt line " + (i + 1).ToString(CultureInfo.InvariantCulture);
                var e = line.Split((char[])null, StringSplitOptions.RemoveEmptyEntries);
                if (e.Length < 5 || !int.TryParse(e[0], NumberStyles.Integer, CultureInfo.InvariantCulture, out var id) ||
                    !int.TryParse(e[2], NumberStyles.Integer, CultureInfo.InvariantCulture, out var w) ||
                    !int.TryParse(e[3], NumberStyles.Integer, CultureInfo.InvariantCulture, out var h) || w < 1 || h < 1 ||
                    !Numbers(e, 4, e.Length - 4, out var p))
                {
                    problems.Add(new ValidationProblem(field, line, "is not CAMERA_ID MODEL WIDTH HEIGHT PARAMS[].", "Write the model with COLMAP's text exporter."));
                    continue;
                }
                double fx, fy, cx, cy;
                int expected;
                var distortion = 0;
                switch (e[1])
                {
                    case "SIMPLE_PINHOLE": expected = 3; fx = fy = At(p, 0); cx = At(p, 1); cy = At(p, 2); break;
                    case "PINHOLE": expected = 4; fx = At(p, 0); fy = At(p, 1); cx = At(p, 2); cy = At(p, 3); break;
                    case "SIMPLE_RADIAL": expected = 4; fx = fy = At(p, 0); cx = At(p, 1); cy = At(p, 2); distortion = 3; break;
                    case "RADIAL": expected = 5; fx = fy = At(p, 0); cx = At(p, 1); cy = At(p, 2); distortion = 3; break;
                    case "OPENCV": expected = 8; fx = At(p, 0); fy = At(p, 1); cx = At(p, 2); cy = At(p, 3); distortion = 4; break;
                    default:
                        problems.Add(new ValidationProblem(field + " (MODEL)", e[1], "is a camera model a Unity camera cannot reproduce.",
                            "Undistort the model to PINHOLE first (`colmap image_undistorter`)."));
                        continue;
                }
                if (p.Length != expected || !(fx > 0) || !(fy > 0))
                {
                    problems.Add(new ValidationProblem(field, line, "has the wrong parameters for " + e[1] + " (" + expected.ToString(CultureInfo.InvariantCulture) + " numbers, focal lengths above 0).", "Write the model with COLMAP's text exporter."));
                    continue;
                }
                if (distortion > 0 && p.Skip(distortion).Any(x => x != 0))
                    warnings.Add(new ValidationProblem(field + " (" + e[1] + ")", string.Join(" ", e.Skip(4 + distortion)),
                        "describes lens distortion, which a Unity camera does not reproduce: the pinhole part is imported, the distortion is not.",
                        "Undistort the model to PINHOLE first (`colmap image_undistorter`) to compare like with like."));
                result[id] = new ImportedIntrinsics(2 * Math.Atan(0.5 * w / fx), w, h, fx, fy, cx, cy);
            }
            return result;
        }

        static double At(double[] p, int i) => i < p.Length ? p[i] : double.NaN;

        static bool Numbers(string[] e, int first, int count, out double[] values)
        {
            values = new double[Math.Max(0, count)];
            for (var i = 0; i < count; i++)
                if (!double.TryParse(e[first + i], NumberStyles.Float, CultureInfo.InvariantCulture, out values[i]) || double.IsNaN(values[i]) || double.IsInfinity(values[i]))
                    return false;
            return true;
        }

        static InvalidParameterException Fail(string field, string value, string reason, string fix) =>
            new InvalidParameterException(new[] { new ValidationProblem(field, value, reason, fix) });
    }
}
