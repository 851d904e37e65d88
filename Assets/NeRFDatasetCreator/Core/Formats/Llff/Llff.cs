using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The maths of LLFF's <c>poses_bounds.npy</c>, each rule from the code that writes or reads it:
    /// <list type="bullet">
    /// <item>One row of 17 numbers per image: the 3 × 5 matrix [c0 c1 c2 | t | hwf] flattened row by row, then near and
    /// far (Fyusion/LLFF c6e27b1 llff/poses/pose_utils.py:85, <c>poses[..., i].ravel()</c> + <c>[close_depth, inf_depth]</c>;
    /// read back by bmild/nerf 14c5556 load_llff.py:64–66, <c>poses_arr[:, :-2].reshape([-1, 3, 5])</c>).</item>
    /// <item>The rotation's columns are the camera's down, right and back axes in the world: pose_utils.py:50–51 turns
    /// COLMAP's [right, down, forward] into <c>[-u, r, -t]</c>, and load_llff.py:250 turns them back into OpenGL's
    /// [right, up, back] with <c>[c1, −c0, c2]</c>. Our c2w is OpenGL already, so c0 = −y, c1 = x, c2 = z.</item>
    /// <item>hwf: image height, width and the focal length in pixels (pose_utils.py:23); one focal for both axes and the
    /// principal point at the image centre (bmild/nerf run_nerf_helpers get_rays: <c>(i − W/2)/focal</c>).</item>
    /// <item>Near and far are z-distances along the camera axis (pose_utils.py:73, 82): <see cref="DepthBounds"/>.</item>
    /// </list>
    /// </summary>
    public static class Llff
    {
        public const string FolderName = "llff";
        public const string PosesBoundsFileName = "poses_bounds.npy";
        public const string ImagesFolder = "images";


        /// <summary>bmild/nerf run_nerf.py:557, 600: <c>--llffhold 8</c> tests on images 0, 8, 16 … of the sorted list.</summary>
        public const int HoldEvery = 8;

        /// <summary>The 17 numbers of one image's row.</summary>
        public static double[] Row(Matrix4x4d cameraToWorld, int height, int width, double focal, double near, double far)
        {
            var hwf = new[] { height, width, focal };
            var row = new double[17];
            for (var r = 0; r < 3; r++)
            {
                row[5 * r] = -cameraToWorld[r, 1];
                row[5 * r + 1] = cameraToWorld[r, 0];
                row[5 * r + 2] = cameraToWorld[r, 2];
                row[5 * r + 3] = cameraToWorld[r, 3];
                row[5 * r + 4] = hwf[r];
            }
            row[15] = near;
            row[16] = far;
            return row;
        }

        /// <summary>
        /// The name of image <paramref name="index"/> of <paramref name="count"/>: the number, zero-padded to one width
        /// (at least 4 digits) so that the loaders' <c>sorted(os.listdir)</c> (load_llff.py:96) is the pose order.
        /// </summary>
        public static string ImageName(int index, int count) =>
            index.ToString("D" + Math.Max(4, (Math.Max(1, count) - 1).ToString(CultureInfo.InvariantCulture).Length), CultureInfo.InvariantCulture) + ".png";

        /// <summary>
        /// Why a camera cannot be written as hwf, or null: one focal (fx = fy) and the principal point at the image centre,
        /// as get_rays assumes (lens shift moves it).
        /// </summary>
        public static ValidationProblem CameraRefusal(CameraIntrinsics k, string target)
        {
            if (Math.Abs(k.FlX - k.FlY) <= 1e-9 * k.FlX && Math.Abs(k.Cx - k.Width / 2.0) <= 1e-9 && Math.Abs(k.Cy - k.Height / 2.0) <= 1e-9) return null;
            return new ValidationProblem("--to", target,
                "holds one focal length and puts the principal point at the image centre (poses_bounds.npy's hwf), but this dataset's camera has fx " + ValidationProblem.Format(k.FlX) +
                ", fy " + ValidationProblem.Format(k.FlY) + ", principal point (" + ValidationProblem.Format(k.Cx) + ", " + ValidationProblem.Format(k.Cy) + ") for " + k.Width + " × " + k.Height + ".",
                "Capture without lens shift, or convert to nerfstudio or colmap, which hold any principal point.");
        }

        /// <summary>Why a distorted dataset cannot go to <paramref name="target"/> (a pinhole format), or null.</summary>
        public static ValidationProblem LensRefusal(LensDistortion lens, string target) => lens == null ? null :
            new ValidationProblem("--to", target, "holds pinhole cameras only, and this dataset's images were taken through " + lens.Describe() + ".",
                "Undistort the images to a pinhole first, or convert to nerfstudio or colmap, which carry the lens.");
    }
}
