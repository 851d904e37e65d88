using System;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What aras-p's Gaussian Splatting package (org.nesnausk.gaussian-splatting, github.com/aras-p/UnityGaussianSplatting at
    /// 2c6fed37da67a217367261fcfcd3316d34c73e76, file paths below under <c>package/</c>) does with a PLY and its
    /// <c>cameras.json</c>, re-stated engine-free so the Editor can predict it and tests can check it
    /// (Documentation~/maintainers/splat-placement-editor.md has the line-by-line reading).
    /// </summary>
    public static class ArasPSplatConventions
    {
        /// <summary>The field of view every imported camera gets (Editor/GaussianSplatAssetCreator.cs:1112, <c>fov = 25 //@TODO</c>).</summary>
        public const double ImportedFovDegrees = 25;

        /// <summary>
        /// One camera as the asset creator imports a 3DGS <c>cameras.json</c> entry (GaussianSplatAssetCreator.cs:1097-1113):
        /// pos = position; axisX, axisY, axisZ = columns 0, 1, 2 of <c>rotation</c> (<c>rotation[row][column]</c>), then
        /// axisY and axisZ negated. In the splat object's local frame (the PLY's).
        /// </summary>
        public static ArasPCamera Import(double[] position, double[][] rotation)
        {
            if (position == null || position.Length != 3) throw new ArgumentException("position has 3 numbers.", nameof(position));
            if (rotation == null || rotation.Length != 3 || rotation.Any(r => r == null || r.Length != 3)) throw new ArgumentException("rotation is 3×3.", nameof(rotation));
            var axisX = new Vector3d(rotation[0][0], rotation[1][0], rotation[2][0]);
            var axisY = new Vector3d(rotation[0][1], rotation[1][1], rotation[2][1]);
            var axisZ = new Vector3d(rotation[0][2], rotation[1][2], rotation[2][2]);
            return new ArasPCamera(new Vector3d(position[0], position[1], position[2]), axisX, -axisY, -axisZ, ImportedFovDegrees);
        }

        /// <summary>
        /// The local rotation <c>GaussianSplatRenderer.ActivateCamera</c> gives the main camera while it is parented to the
        /// splat object: <c>Quaternion.LookRotation(cam.axisZ, cam.axisY)</c> (Runtime/GaussianSplatRenderer.cs:674).
        /// </summary>
        public static Quaterniond ActivatedLocalRotation(ArasPCamera camera) => Quaterniond.LookRotation(camera.AxisZ, camera.AxisY);

        /// <summary>
        /// The asset's name the creator gives a PLY (GaussianSplatAssetCreator.cs:293,
        /// <c>Path.GetFileNameWithoutExtension(FilePickerControl.PathToDisplayString(m_InputFile))</c>; Editor/Utils/FilePickerControl.cs:24-42):
        /// the file name, unless it is "point_cloud", "splat" or "input", then the last four path parts joined by '-'.
        /// </summary>
        public static string AssetName(string plyPath)
        {
            if (string.IsNullOrWhiteSpace(plyPath)) return "<none>";
            var path = plyPath.Replace('\\', '/');
            var parts = path.Split('/');
            var baseName = Path.GetFileNameWithoutExtension(parts[parts.Length - 1]).ToLowerInvariant();
            string display;
            if (baseName != "point_cloud" && baseName != "splat" && baseName != "input") display = parts[parts.Length - 1];
            else
            {
                if (parts.Length >= 4) path = string.Join("/", parts.Skip(parts.Length - 4));
                display = path.Replace('/', '-');
            }
            return Path.GetFileNameWithoutExtension(display);
        }

        /// <summary>
        /// The cameras.json the creator imports for <paramref name="plyPath"/> (GaussianSplatAssetCreator.cs:1073-1083): the
        /// first <c>cameras.json</c> in the PLY's folder or a parent, walking up while the folder exists; null when none.
        /// </summary>
        public static string CamerasJsonFor(string plyPath)
        {
            var current = plyPath;
            while (true)
            {
                var dir = Path.GetDirectoryName(current);
                if (string.IsNullOrEmpty(dir) || !Directory.Exists(dir)) return null;
                var candidate = dir + "/cameras.json";
                if (File.Exists(candidate)) return candidate;
                current = dir;
            }
        }
    }

    /// <summary>aras-p's <c>GaussianSplatAsset.CameraInfo</c> (Runtime/GaussianSplatAsset.cs:240-245): pos, axisX/Y/Z, fov.</summary>
    public sealed class ArasPCamera
    {
        public ArasPCamera(Vector3d position, Vector3d axisX, Vector3d axisY, Vector3d axisZ, double fov)
        {
            Position = position;
            AxisX = axisX;
            AxisY = axisY;
            AxisZ = axisZ;
            Fov = fov;
        }

        public Vector3d Position { get; }
        public Vector3d AxisX { get; }
        public Vector3d AxisY { get; }
        public Vector3d AxisZ { get; }
        public double Fov { get; }
    }
}
