using System;

namespace NerfDatasetCreator
{
    /// <summary>How the camera moves while the shutter is open (<see cref="MotionBlurSettings.Camera"/>).</summary>
    public enum ShutterCameraMotion
    {
        /// <summary>
        /// Along the split's own path: the camera's velocity at a view is estimated from its neighbours in the split's
        /// order (formation order, file order, an animated camera's samples) and the shutter covers
        /// <see cref="MotionBlurSettings.Shutter"/> of the spacing between consecutive views.
        /// </summary>
        Path,

        /// <summary>A seeded random shake per view: the centre moves <see cref="MotionBlurSettings.ShakeDistance"/> and the camera turns <see cref="MotionBlurSettings.ShakeDegrees"/> over the shutter.</summary>
        Shake,

        /// <summary>The camera stands still; only the content moves (dynamic captures).</summary>
        Still,
    }

    /// <summary>
    /// The <c>motionBlur</c> section of the settings (Documentation~/motion-blur.md). Off by default: nothing changes.
    /// On, every view is exposed over a shutter interval centred on its planned pose (which stays the written
    /// <c>transform_matrix</c>): the camera moves from a start to an end pose, and in a dynamic capture the content moves
    /// over <see cref="Shutter"/> of a time step. The colour image is the average, in linear light, of
    /// <see cref="SubFrames"/> renders at the sub-frame times (k + ½)/N of the interval (<see cref="SubFrameSchedule"/>);
    /// depth, normals and masks are rendered once at the mid pose, as is the sharp image written beside the blurred one.
    /// With <see cref="Readout"/> &gt; 0 the rows are exposed one after the other (rolling shutter).
    /// </summary>
    [Serializable]
    public sealed class MotionBlurSettings
    {
        public const int MaxSubFrames = 256;
        public const int DefaultSubFrames = 16;
        public const double MaxShakeDegrees = 45;
        public const double MaxReadout = 0.95;

        public bool Enabled;

        public ShutterCameraMotion Camera = ShutterCameraMotion.Path;

        /// <summary>
        /// The exposure as a fraction of the spacing between consecutive views (path) and of a time step (content of a
        /// dynamic capture), in (0, 1]: 0.5 is film's 180° shutter.
        /// </summary>
        public double Shutter = 0.5;

        /// <summary>Renders averaged per view (2 … 256). The error bound for N is in Documentation~/motion-blur.md.</summary>
        public int SubFrames = DefaultSubFrames;

        /// <summary>Shake: how far the camera centre moves over the shutter, in Unity units.</summary>
        public double ShakeDistance;

        /// <summary>Shake: how far the camera turns over the shutter, in degrees.</summary>
        public double ShakeDegrees;

        /// <summary>
        /// Rolling shutter: the fraction of the interval over which the rows start, top row first; each row is exposed
        /// for the remaining 1 − readout. 0 is a global shutter.
        /// </summary>
        public double Readout;

        public MotionBlurSettings Clone() => (MotionBlurSettings)MemberwiseClone();

        static readonly string[] Names = { "path", "shake", "still" };

        public static string CameraName(ShutterCameraMotion motion) => (int)motion >= 0 && (int)motion < Names.Length ? Names[(int)motion] : ((int)motion).ToString(System.Globalization.CultureInfo.InvariantCulture);

        public static string CameraNameList() => "\"path\", \"shake\", \"still\"";

        public static bool TryParseCamera(string name, out ShutterCameraMotion motion)
        {
            for (var i = 0; i < Names.Length; i++)
                if (string.Equals(name, Names[i], StringComparison.OrdinalIgnoreCase))
                {
                    motion = (ShutterCameraMotion)i;
                    return true;
                }
            motion = ShutterCameraMotion.Path;
            return false;
        }
    }
}
