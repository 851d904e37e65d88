using System;
using System.Collections.Generic;
using System.IO;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A 3DGS-format <c>cameras.json</c> of the dataset's train cameras in the PLY's frame, for aras-p's importer's camera
    /// slider. Each entry is what graphdeco's <c>camera_to_JSON</c> writes (utils/camera_utils.py): <c>position</c> the
    /// camera centre, <c>rotation</c> the camera-to-world rotation in OpenCV axes (x right, y down, z forward) as rows,
    /// <c>fx = fov2focal(FovX, width)</c> and <c>fy = fov2focal(FovY, height)</c> — for the Blender reader, which takes
    /// FovY from FovX's focal length, fy = fx = width / (2·tan(camera_angle_x / 2)). Keys in graphdeco's order.
    /// </summary>
    public static class SplatCamerasJson
    {
        public const string FileName = "cameras.json";

        /// <summary>
        /// The entries for the dataset's train split, every camera moved by <paramref name="outputToTrainer"/> as the
        /// trainer moved it: centre through the map, rotation through its 3×3 with each column renormalised (a
        /// similarity's uniform scale; gsplat's transform_cameras does the same).
        /// </summary>
        public static JArray Build(string datasetDir, Matrix4x4d outputToTrainer)
        {
            var root = Path.GetFullPath(datasetDir);
            if (!File.Exists(DatasetFolder.SplitPath(root, "train")))
                throw new InvalidParameterException(new[] { new ValidationProblem("dataset", root, "has no transforms_train.json, so there are no train cameras.", "Pass the dataset folder (transforms_train.json and dataset_config.json).") });
            var split = DatasetFolder.ReadSplit(root, "train", DatasetReadMode.Lenient);
            var cameras = new JArray();
            var id = 0;
            foreach (var frame in split.Frames)
            {
                if (!(frame.TransformMatrix is Matrix4x4d c2w)) continue;
                var size = Size(split, frame);
                var angle = frame.Intrinsics.AngleX ?? split.Intrinsics.AngleX ?? split.CameraAngleX;
                var flX = frame.Intrinsics.FlX ?? split.Intrinsics.FlX;
                double fx, fy;
                if (angle is double a) fx = fy = size.W / (2 * Math.Tan(a / 2)); // Blender reader: FovY from FovX's focal
                else if (flX is double f) { fx = f; fy = frame.Intrinsics.FlY ?? split.Intrinsics.FlY ?? f; }
                else throw Refuse(split.FileName, "has neither camera_angle_x nor fl_x, so the cameras' focal length is unknown.");
                cameras.Add(Entry(id, ImageName(frame.FilePath, id), size.W, size.H, Move(c2w, outputToTrainer), fx, fy));
                id++;
            }
            if (cameras.Count == 0) throw Refuse(split.FileName, "has no frame with a transform_matrix, so there is no train camera to write.");
            return cameras;
        }

        /// <summary>One graphdeco entry from an OpenGL camera-to-world (our transform_matrix) in the PLY's frame.</summary>
        public static JObject Entry(int id, string imageName, int width, int height, Matrix4x4d cameraToWorldOpenGl, double fx, double fy)
        {
            // camera_to_JSON inverts Rt = [R^T | T] = world-to-camera (OpenCV axes), so position is the centre and
            // rotation the OpenCV camera-to-world rotation: our columns with y and z negated (the Blender reader's flip).
            var right = cameraToWorldOpenGl.Column(0);
            var down = -cameraToWorldOpenGl.Column(1);
            var forward = -cameraToWorldOpenGl.Column(2);
            var centre = cameraToWorldOpenGl.Translation;
            return new JObject
            {
                ["id"] = id,
                ["img_name"] = imageName,
                ["width"] = width,
                ["height"] = height,
                ["position"] = new JArray(centre.X, centre.Y, centre.Z),
                ["rotation"] = new JArray(new JArray(right.X, down.X, forward.X), new JArray(right.Y, down.Y, forward.Y), new JArray(right.Z, down.Z, forward.Z)),
                ["fy"] = fy,
                ["fx"] = fx,
            };
        }

        /// <summary>A camera-to-world moved by a similarity: centre mapped, rotation columns mapped and renormalised.</summary>
        public static Matrix4x4d Move(Matrix4x4d c2w, Matrix4x4d map)
        {
            var x = map.MultiplyVector(c2w.Column(0)).Normalized();
            var y = map.MultiplyVector(c2w.Column(1)).Normalized();
            var z = map.MultiplyVector(c2w.Column(2)).Normalized();
            return Matrix4x4d.FromColumns(x, y, z, map.MultiplyPoint(c2w.Translation));
        }

        /// <summary>3DGS's Blender reader: <c>Path(file_path + extension).stem</c>, the file name without folder and extension.</summary>
        static string ImageName(string filePath, int id)
        {
            if (string.IsNullOrEmpty(filePath)) return "view_" + id;
            var name = filePath.Replace('\\', '/');
            name = name.Substring(name.LastIndexOf('/') + 1);
            var dot = name.LastIndexOf('.');
            return dot > 0 && (name.EndsWith(".png", StringComparison.OrdinalIgnoreCase) || name.EndsWith(".jpg", StringComparison.OrdinalIgnoreCase)) ? name.Substring(0, dot) : name;
        }

        static (int W, int H) Size(DatasetSplitFile split, DatasetFrame frame)
        {
            var w = frame.Intrinsics.W ?? split.Intrinsics.W ?? (double?)split.W;
            var h = frame.Intrinsics.H ?? split.Intrinsics.H ?? (double?)split.H;
            if (w is double wv && h is double hv && wv >= 1 && hv >= 1) return ((int)Math.Round(wv), (int)Math.Round(hv));
            var image = frame.Image;
            if (image != null && image.Exists && image.FullPath.EndsWith(".png", StringComparison.OrdinalIgnoreCase))
            {
                var png = PngInfo.Read(image.FullPath);
                return (png.Width, png.Height);
            }
            throw Refuse(split.FileName, "has no w and h and frame " + frame.Index + "'s image cannot be read for its size.", "Write w and h into the transforms file, or render the images.");
        }

        /// <summary>
        /// Where aras-p's importer finds a cameras.json for <paramref name="plyPath"/>: it walks up from the PLY's folder
        /// and takes the first <c>cameras.json</c> (GaussianSplatAssetCreator.LoadJsonCamerasFile); null when none.
        /// </summary>
        public static string ViewerWillRead(string plyPath)
        {
            var dir = Path.GetDirectoryName(Path.GetFullPath(plyPath));
            while (!string.IsNullOrEmpty(dir) && Directory.Exists(dir))
            {
                var candidate = Path.Combine(dir, FileName);
                if (File.Exists(candidate)) return candidate;
                dir = Path.GetDirectoryName(dir);
            }
            return null;
        }

        static InvalidParameterException Refuse(string file, string reason, string fix = "Write the dataset again with this plugin, or pass one whose transforms_train.json has camera_angle_x, w and h.") =>
            new InvalidParameterException(new[] { new ValidationProblem(file ?? "transforms_train.json", "train", reason, fix) });
    }
}
