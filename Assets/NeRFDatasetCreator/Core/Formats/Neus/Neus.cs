using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The maths of IDR's / NeuS's <c>cameras_sphere.npz</c> (Totoro97/NeuS 6e0a230 models/dataset.py), each rule from
    /// the loader's code:
    /// <list type="bullet">
    /// <item>Per image i, <c>world_mat_i</c> and <c>scale_mat_i</c> (4 × 4, lines 60, 65); the loader projects with
    /// <c>P = world_mat @ scale_mat</c> and splits <c>P[:3, :4]</c> with <c>cv.decomposeProjectionMatrix</c> into K, the
    /// camera-to-world rotation Rᵀ and the camera centre (<c>load_K_Rt_from_P</c>, lines 13–34, 70–73).</item>
    /// <item><c>world_mat = K·[R | t]</c> (padded to 4 × 4) with [R | t] our world-to-camera in OpenCV axes: the loader's
    /// rays are <c>K⁻¹·(x, y, 1)</c> rotated by the pose (lines 120–124), x right, y down, looking along +z.</item>
    /// <item><c>scale_mat</c> maps the unit sphere onto the region to reconstruct: "we assume the scene to render is
    /// inside a unit sphere at origin" (line 64); ours is the target's bounding sphere, exact from the capture's record
    /// (<see cref="DatasetTargetReach.Sphere"/>): [[r, 0, 0, cx], [0, r, 0, cy], [0, 0, r, cz], [0, 0, 0, 1]].</item>
    /// <item>Rays go through integer pixel indices (<c>torch.randint(0, W)</c>, line 116; <c>linspace(0, W − 1)</c>,
    /// line 102), where our pixel i has its centre at i + ½: so K's principal point is (W/2 − ½, H/2 − ½) and every
    /// ray passes through a pixel centre.</item>
    /// <item>Images <c>image/*.png</c> and masks <c>mask/*.png</c>, each list sorted by name (lines 53, 56): file k is
    /// camera k, so names are zero-padded to one width (<c>000.png</c>, as the released data).</item>
    /// </list>
    /// </summary>
    public static class Neus
    {
        public const string FolderName = "neus";
        public const string CamerasFileName = "cameras_sphere.npz";
        public const string ImageFolder = "image";
        public const string MaskFolder = "mask";

        /// <summary>OpenGL camera axes (x right, y up, looking along −z) to OpenCV's (x right, y down, along +z).</summary>
        static readonly Matrix4x4d OpenGlToOpenCv = Matrix4x4d.FromRowMajor(
            1, 0, 0, 0,
            0, -1, 0, 0,
            0, 0, -1, 0,
            0, 0, 0, 1);

        /// <summary>The loader's K: our focal lengths, the principal point moved half a pixel so that integer pixels are pixel centres.</summary>
        public static Matrix4x4d K(CameraIntrinsics k) => Matrix4x4d.FromRowMajor(
            k.FlX, 0, k.Cx - 0.5, 0,
            0, k.FlY, k.Cy - 0.5, 0,
            0, 0, 1, 0,
            0, 0, 0, 1);

        /// <summary><c>world_mat_i</c> = K·w2c (OpenCV axes) of our camera-to-world (Blender world, OpenGL axes).</summary>
        public static Matrix4x4d WorldMat(Matrix4x4d cameraToWorld, CameraIntrinsics intrinsics) =>
            K(intrinsics) * (cameraToWorld * OpenGlToOpenCv).InverseRigid();

        /// <summary><c>scale_mat_i</c>: the unit sphere onto the sphere of <paramref name="radius"/> about <paramref name="centre"/>.</summary>
        public static Matrix4x4d ScaleMat(Vector3d centre, double radius) => Matrix4x4d.FromRowMajor(
            radius, 0, 0, centre.X,
            0, radius, 0, centre.Y,
            0, 0, radius, centre.Z,
            0, 0, 0, 1);

        /// <summary>Image or mask <paramref name="index"/> of <paramref name="count"/>: zero-padded to at least 3 digits, one width for all.</summary>
        public static string FileName(int index, int count) =>
            index.ToString("D" + Math.Max(3, (Math.Max(1, count) - 1).ToString(CultureInfo.InvariantCulture).Length), CultureInfo.InvariantCulture) + ".png";

        /// <summary>
        /// NeuS's mask: 255 where the source (our mask, or the image's alpha) is at least half on, else 0 — the loader
        /// divides by 256 and keeps values above 0.5 (models/dataset.py:57, exp_runner.py:115), so a binary mask is read
        /// exactly as meant.
        /// </summary>
        public static byte[] Mask(byte[] samples, int channels, int offset, int pixels)
        {
            var mask = new byte[pixels];
            for (var i = 0; i < pixels; i++) mask[i] = samples[channels * i + offset] >= 128 ? (byte)255 : (byte)0;
            return mask;
        }
    }
}
