using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The names of an NSFF scene folder as Neural Scene Flow Fields reads it (zhengqili/Neural-Scene-Flow-Fields
    /// d400175, nsff_exp/load_llff.py <c>_load_data</c> and run_nerf_helpers.py <c>read_optical_flow</c>; citations in
    /// Documentation~/maintainers/layouts-flow.md): <c>poses_bounds.npy</c>; <c>images/</c> (the first image gives the
    /// size, load_llff.py:20–22) and <c>images_&lt;W&gt;x&lt;H&gt;/</c> (read with <c>--final_height H</c>:
    /// load_llff.py:30–34, 44); <c>disp/*.npy</c> (load_llff.py:77–86); <c>motion_masks/*.png</c> (88–96);
    /// <c>flow_i1/%05d_fwd.npz</c> and <c>%05d_bwd.npz</c> with keys <c>flow</c> and <c>mask</c>
    /// (run_nerf_helpers.py:579–600).
    /// </summary>
    public static class Nsff
    {
        public const string FolderName = "nsff";
        public const string RecordFileName = "nsff_export.json";
        public const string ImagesFolder = "images";
        public const string DispFolder = "disp";
        public const string MotionMasksFolder = "motion_masks";
        public const string FlowFolder = "flow_i1";

        /// <summary>run_nerf.py:114, <c>--target_idx</c> default 10: load_llff.py:348 indexes <c>poses[target_idx]</c>, so a shorter video needs a smaller one.</summary>
        public const int DefaultTargetIdx = 10;

        /// <summary>The folder NSFF reads images from with <c>--final_height H</c>: <c>images_{W}x{H}</c> (load_llff.py:30–34).</summary>
        public static string SizedImagesFolder(int width, int height) => ImagesFolder + "_" + width.ToString(CultureInfo.InvariantCulture) + "x" + height.ToString(CultureInfo.InvariantCulture);

        /// <summary>Frame t's name stem: <c>00000</c> (NSFF's scripts name frames <c>%05d</c>, run_flows_video.py:337, 416).</summary>
        public static string Stem(int frame) => frame.ToString("00000", CultureInfo.InvariantCulture);

        /// <summary><c>flow_i1/%05d_fwd.npz</c> (frame t → t + 1) or <c>%05d_bwd.npz</c> (t → t − 1), run_nerf_helpers.py:584–585, 593–594.</summary>
        public static string FlowFile(int frame, bool forward) => FlowFolder + "/" + Stem(frame) + (forward ? "_fwd.npz" : "_bwd.npz");
    }
}
