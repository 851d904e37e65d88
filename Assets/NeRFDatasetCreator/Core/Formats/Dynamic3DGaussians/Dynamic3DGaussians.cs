using System;
using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The maths and pixels of the Dynamic 3D Gaussians layout (JonathonLuiten/Dynamic3DGaussians 7dbbd4d), each rule
    /// from the loader's code:
    /// <list type="bullet">
    /// <item>Cameras: <c>setup_camera</c> (helpers.py:8–31) takes fx, fy, cx, cy from <c>k</c> and a world-to-camera
    /// matrix <c>w2c</c> in OpenCV camera axes (x right, y down, looking along +z; README "Camera Coordinate System").</item>
    /// <item>World: the training loss has a floor term, <c>clamp(fg_pts[:, 1], min=0)</c> (train.py:114, weight 2
    /// on line 122), that pushes foreground points to y ≤ 0: the CMU Panoptic world has +y down and its floor at
    /// y = 0. Our output world (Blender: +Z up) is therefore turned by −90° about X, (x, y, z) → (x, −z, y), and moved
    /// so that the floor plane lies under everything the target reaches (<see cref="World"/>): the term stays 0.</item>
    /// <item>Images: <c>Image.open</c> → <c>/ 255</c> with every channel fed to a 3-channel loss (train.py:21–22, 87),
    /// so RGB, composited over black — the rasterizer's background (helpers.py:23, <c>bg=[0, 0, 0]</c>).</item>
    /// <item>Segmentation: one channel read as float, <c>seg_col = stack(seg, 0, 1 − seg)</c> (train.py:23–25),
    /// so 8-bit grey with 1 on the target and 0 elsewhere.</item>
    /// <item>Initial cloud: N × 7 (xyz, rgb in [0, 1], seg) under key <c>data</c> (train.py:38–46). Background points
    /// (seg 0) are needed: from time step 1 the loss averages over them (<c>l1_loss_v2(bg_pts, …)</c>, train.py:116–118,
    /// helpers.py:50–51), which is NaN for none; and the seg loss expects background pixels (seg (0, 0, 1)) rendered by them.
    /// A shell of <see cref="ShellPoints"/> points around every camera, in the background colour, provides them.</item>
    /// </list>
    /// </summary>
    public static class Dynamic3DGaussians
    {
        public const string FolderName = "dynamic3dgs";
        public const string TrainMetaFileName = "train_meta.json";
        public const string TestMetaFileName = "test_meta.json";
        public const string ImagesFolder = "ims";
        public const string SegmentationFolder = "seg";
        public const string PointCloudFileName = "init_pt_cld.npz";
        public const string PointCloudKey = "data";

        /// <summary>train.py:40, <c>max_cams = 50</c>: the per-camera colour terms <c>cam_m</c>, <c>cam_c</c> have 50 rows, indexed by the camera's position in a step.</summary>
        public const int MaxCameras = 50;

        /// <summary>Background points on the shell: spacing ≈ 2r·√(4π/N), about 0.05 of the cameras' distance for N = 20 000.</summary>
        public const int ShellPoints = 20000;

        /// <summary>The shell's radius over the cameras' largest distance from their mean centre.</summary>
        public const double ShellRadiusFactor = 2;

        /// <summary>OpenGL camera axes (x right, y up, looking along −z) to OpenCV's (x right, y down, along +z).</summary>
        static readonly Matrix4x4d OpenGlToOpenCv = Matrix4x4d.FromRowMajor(
            1, 0, 0, 0,
            0, -1, 0, 0,
            0, 0, -1, 0,
            0, 0, 0, 1);

        /// <summary>
        /// Output world → this layout's world: p_d = R·(p − (0, 0, floorZ)) with R (x, y, z) = (x, −z, y), a proper
        /// rotation (+y down). Every point at or above <paramref name="floorZ"/> (output units) ends at y ≤ 0.
        /// </summary>
        public static Matrix4x4d World(double floorZ) => Matrix4x4d.FromRowMajor(
            1, 0, 0, 0,
            0, 0, -1, floorZ,
            0, 1, 0, 0,
            0, 0, 0, 1);

        /// <summary>The floor under a target reaching <paramref name="reach"/> output units from the output origin.</summary>
        public static double FloorUnder(double reach) => -reach;

        /// <summary><c>w2c</c>: the inverse of our camera-to-world (Blender world, OpenGL axes) in this layout's world with OpenCV axes.</summary>
        public static Matrix4x4d WorldToCamera(Matrix4x4d cameraToWorld, Matrix4x4d world) =>
            (world * cameraToWorld * OpenGlToOpenCv).InverseRigid();

        /// <summary><c>k</c>: [[fx, 0, cx], [0, fy, cy], [0, 0, 1]] in pixels (the same principal point as our COLMAP export).</summary>
        public static double[][] K(CameraIntrinsics intrinsics) => new[]
        {
            new[] { intrinsics.FlX, 0, intrinsics.Cx },
            new[] { 0, intrinsics.FlY, intrinsics.Cy },
            new[] { 0.0, 0, 1 },
        };

        /// <summary><c>fn</c>: "&lt;camera id&gt;/&lt;step, 6 digits&gt;.png" as in the released data (ims/ and seg/ share it).</summary>
        public static string FileName(int cameraId, int step) =>
            cameraId.ToString(CultureInfo.InvariantCulture) + "/" + step.ToString("D6", CultureInfo.InvariantCulture) + ".png";

        /// <summary>
        /// 8-bit RGB over black from an 8-bit RGB or straight-alpha RGBA image: c·a/255, rounded — the over operator
        /// the loaders apply to straight-alpha sRGB values (NeRF's <c>rgb * a + bg * (1 − a)</c> with bg 0).
        /// </summary>
        public static byte[] RgbOverBlack(PngImage image)
        {
            if (image.BitDepth != 8 || (image.ColorType != PngInfo.ColorTypeRgba && image.ColorType != PngInfo.ColorTypeRgb))
                throw new ArgumentException("expects an 8-bit RGB or RGBA image, not colour type " + image.ColorType + " at " + image.BitDepth + " bits.", nameof(image));
            var pixels = image.Width * image.Height;
            var rgb = new byte[pixels * 3];
            var s = image.Samples;
            if (image.ColorType == PngInfo.ColorTypeRgb)
            {
                Buffer.BlockCopy(s, 0, rgb, 0, rgb.Length);
                return rgb;
            }
            for (var i = 0; i < pixels; i++)
            {
                int a = s[4 * i + 3];
                for (var c = 0; c < 3; c++) rgb[3 * i + c] = (byte)((s[4 * i + c] * a + 127) / 255);
            }
            return rgb;
        }

        /// <summary>
        /// 0/1 segmentation: 1 where the source is at least half on — an 8-bit grey mask (ours: 255 on the target), or
        /// the alpha channel of an 8-bit RGBA image.
        /// </summary>
        public static byte[] Segmentation(PngImage image)
        {
            int channels, offset;
            if (image.BitDepth == 8 && image.ColorType == PngInfo.ColorTypeGray) { channels = 1; offset = 0; }
            else if (image.BitDepth == 8 && image.ColorType == PngInfo.ColorTypeRgba) { channels = 4; offset = 3; }
            else throw new ArgumentException("expects an 8-bit grey mask or an RGBA image.", nameof(image));
            var seg = new byte[image.Width * image.Height];
            for (var i = 0; i < seg.Length; i++) seg[i] = image.Samples[channels * i + offset] >= 128 ? (byte)1 : (byte)0;
            return seg;
        }

        /// <summary>
        /// The N × 7 rows of <c>init_pt_cld.npz</c>: the target's surface points (output frame, moved by
        /// <paramref name="world"/>; colour / 255; seg 1), then <see cref="ShellPoints"/> golden-spiral points on a sphere
        /// of <see cref="ShellRadiusFactor"/> × the cameras' largest distance from their mean (this layout's world), in
        /// <paramref name="background"/> (sRGB in [0, 1]); seg 0.
        /// </summary>
        public static float[] InitialCloud(IReadOnlyList<CloudPoint> target, Matrix4x4d world, IReadOnlyList<Vector3d> cameraCentres,
            Vector3d background, out int rows)
        {
            var centre = Vector3d.Zero;
            foreach (var c in cameraCentres) centre += c;
            centre /= Math.Max(1, cameraCentres.Count);
            var far = 0.0;
            foreach (var c in cameraCentres) far = Math.Max(far, Vector3d.Distance(c, centre));
            var radius = ShellRadiusFactor * Math.Max(far, 1e-3);

            rows = target.Count + ShellPoints;
            var data = new float[rows * 7];
            var row = 0;
            foreach (var p in target)
            {
                var q = world.MultiplyPoint(p.Position);
                Put(data, row++, q, new Vector3d(p.Red / 255.0, p.Green / 255.0, p.Blue / 255.0), 1);
            }
            var golden = Math.PI * (3 - Math.Sqrt(5));
            for (var i = 0; i < ShellPoints; i++)
            {
                var y = 1 - 2 * (i + 0.5) / ShellPoints;
                var r = Math.Sqrt(1 - y * y);
                var direction = new Vector3d(r * Math.Cos(golden * i), y, r * Math.Sin(golden * i));
                Put(data, row++, centre + radius * direction, background, 0);
            }
            return data;
        }

        static void Put(float[] data, int row, Vector3d position, Vector3d colour, int seg)
        {
            var o = row * 7;
            data[o] = (float)position.X;
            data[o + 1] = (float)position.Y;
            data[o + 2] = (float)position.Z;
            data[o + 3] = (float)colour.X;
            data[o + 4] = (float)colour.Y;
            data[o + 5] = (float)colour.Z;
            data[o + 6] = seg;
        }
    }
}
