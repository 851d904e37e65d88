using System;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The N3DV ("dynerf") layout as 4DGaussians reads it (hustvl/4DGaussians 843d5ac scene/neural_3D_dataset_NDC.py,
    /// scene/dataset_readers.py readdynerfInfo), each rule from its code:
    /// <list type="bullet">
    /// <item>Detected by <c>poses_bounds.npy</c> (scene/__init__.py:52); one LLFF row per camera (<see cref="Llff.Row"/>),
    /// in the order of the sorted <c>cam*.mp4</c>, whose count must equal the rows (lines 265–268).</item>
    /// <item>Every image is resized to 1352 × 1014 (lines 229–230, 371) and the focal of camera 0 is divided by
    /// 2704 / 1352 = 2 (lines 234, 270–271): the file's focal is for 2704-pixel-wide images, so a 4:3 capture of width W
    /// writes f·2704/W. Other aspects would be stretched: refused. H and W of hwf are not read (overwritten by img_wh);
    /// written as 2028 and 2704, consistent with that focal.</item>
    /// <item>Images: <c>video_path.split('.')[0] + "/images"</c> (line 321) listed and sorted (346), at most
    /// <see cref="MaxFrames"/> (310, 349); image k has time k / 300 (356). The videos are never opened when the image
    /// folder exists (line 324), so each <c>camNN.mp4</c> is an empty placeholder.</item>
    /// <item>Camera 0 is the test camera (<c>eval_index=0</c>, dataset_readers.py:453, 462; lines 313–318).</item>
    /// <item>Initial points: <c>points3D_downsample2.ply</c> with x, y, z, red, green, blue, nx, ny, nz (dataset_readers.py:444, fetchPly 124–130).</item>
    /// </list>
    /// </summary>
    public static class Dynerf
    {
        public const string FolderName = "dynerf";
        public const string PointCloudFileName = "points3D_downsample2.ply";
        public const int LoaderWidth = 1352, LoaderHeight = 1014;

        /// <summary>The width the file's focal refers to (neural_3D_dataset_NDC.py:234: downsample = 2704 / 1352).</summary>
        public const int FocalWidth = 2704;

        /// <summary>The height of a 4:3 image <see cref="FocalWidth"/> wide: hwf's H (not read, written for consistency).</summary>
        public const int FocalHeight = 2028;

        /// <summary>neural_3D_dataset_NDC.py:310, <c>countss = 300</c>: images per camera read, and the time divisor.</summary>
        public const int MaxFrames = 300;

        /// <summary>Whether 4DGaussians' fixed 1352 × 1014 keeps the aspect of W × H: exactly 4:3.</summary>
        public static bool FourByThree(int width, int height) => (long)width * LoaderHeight == (long)height * LoaderWidth;

        /// <summary>The focal the file holds for a focal <paramref name="focal"/> at width <paramref name="width"/>.</summary>
        public static double FileFocal(double focal, int width) => focal * FocalWidth / width;

        /// <summary>The loader's time of image <paramref name="index"/> (line 356).</summary>
        public static double LoaderTime(int index) => index / (double)MaxFrames;

        /// <summary>camNN: two digits at least, one width for all, so that sorted names are camera order.</summary>
        public static string CameraName(int index, int count) =>
            "cam" + index.ToString("D" + Math.Max(2, (Math.Max(1, count) - 1).ToString(CultureInfo.InvariantCulture).Length), CultureInfo.InvariantCulture);

        /// <summary>Image <paramref name="step"/> of a camera: 0000.png … (the released frames' names).</summary>
        public static string ImageName(int step) => step.ToString("D4", CultureInfo.InvariantCulture) + ".png";
    }
}
