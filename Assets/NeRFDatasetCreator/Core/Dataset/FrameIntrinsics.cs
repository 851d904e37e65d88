using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The camera keys of a transforms file or of one frame, each null when absent or not a number: nerfstudio's and
    /// instant-ngp's <c>fl_x fl_y cx cy w h</c> and Blender's <c>camera_angle_x</c> / <c>_y</c>. Frames may override the
    /// file's (nerfstudio and instant-ngp read a frame's keys first).
    /// </summary>
    public sealed class FrameIntrinsics
    {
        public double? W { get; private set; }
        public double? H { get; private set; }
        public double? FlX { get; private set; }
        public double? FlY { get; private set; }
        public double? Cx { get; private set; }
        public double? Cy { get; private set; }
        public double? AngleX { get; private set; }
        public double? AngleY { get; private set; }

        /// <summary>Whether any key is there.</summary>
        public bool Any => W != null || H != null || FlX != null || FlY != null || Cx != null || Cy != null || AngleX != null || AngleY != null;

        public static readonly FrameIntrinsics None = new FrameIntrinsics();

        public static FrameIntrinsics Read(JObject o)
        {
            if (o == null) return None;
            var read = new FrameIntrinsics
            {
                W = Number(o, "w"), H = Number(o, "h"), FlX = Number(o, "fl_x"), FlY = Number(o, "fl_y"),
                Cx = Number(o, "cx"), Cy = Number(o, "cy"), AngleX = Number(o, "camera_angle_x"), AngleY = Number(o, "camera_angle_y"),
            };
            return read.Any ? read : None;
        }

        static double? Number(JObject o, string key) => JsonValues.TryNumber(o[key], out var v) ? v : (double?)null;
    }
}
