using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The problems of the <c>motionBlur</c> section that the settings alone show (<see cref="SettingsValidator"/> adds
    /// them); a shutter that would reach before content time 0 needs the resolved time range and is
    /// <see cref="ShutterPlanning"/>'s.
    /// </summary>
    public static class MotionBlurSettingsValidator
    {
        public static IReadOnlyList<ValidationProblem> Validate(DatasetSettings settings)
        {
            var problems = new List<ValidationProblem>();
            var m = settings.MotionBlur;
            if (m == null || !m.Enabled) return problems;
            void Add(ValidationProblem p)
            {
                if (p != null) problems.Add(p);
            }
            if (!(m.Shutter > 0 && m.Shutter <= 1))
                Add(new ValidationProblem("motionBlur.shutter", ValidationProblem.Format(m.Shutter),
                    "must be more than 0 and at most 1: the exposure as a fraction of the spacing between consecutive views (and of a time step).",
                    "Use e.g. 0.5 (film's 180° shutter)."));
            Add(ValidationProblem.OutsideRange("motionBlur.subFrames", m.SubFrames, 2, MotionBlurSettings.MaxSubFrames));
            Add(ValidationProblem.OutsideRange("motionBlur.readout", m.Readout, 0, MotionBlurSettings.MaxReadout, "(fraction of the shutter interval; 0 = global shutter)"));
            var dynamic = settings.Time != null && settings.Time.Enabled;
            if ((int)m.Camera < 0 || (int)m.Camera > (int)ShutterCameraMotion.Still)
                Add(new ValidationProblem("motionBlur.camera", ((int)m.Camera).ToString(CultureInfo.InvariantCulture), "is not a camera motion.",
                    "Use one of " + MotionBlurSettings.CameraNameList() + "."));
            else if (m.Camera == ShutterCameraMotion.Shake)
            {
                Add(ValidationProblem.OutsideRange("motionBlur.shakeDistance", m.ShakeDistance, 0, 1000, "Unity units"));
                Add(ValidationProblem.OutsideRange("motionBlur.shakeDegrees", m.ShakeDegrees, 0, MotionBlurSettings.MaxShakeDegrees, "degrees"));
                if (m.ShakeDistance == 0 && m.ShakeDegrees == 0 && !dynamic)
                    Add(new ValidationProblem("motionBlur.shakeDistance", "0",
                        "and motionBlur.shakeDegrees are both 0 in a static capture, so nothing moves while the shutter is open.",
                        "Give the shake a distance (Unity units) or an angle (degrees), or use \"camera\": \"path\"."));
            }
            else if (m.Camera == ShutterCameraMotion.Still && !dynamic)
                Add(new ValidationProblem("motionBlur.camera", "\"still\"",
                    "keeps the camera still in a static capture, so nothing moves while the shutter is open.",
                    "Use \"path\" or \"shake\", or a dynamic capture (time.mode) whose content moves."));
            else if (m.Camera == ShutterCameraMotion.Path && dynamic && settings.Time.Mode == TimeMode.MultiView)
                Add(new ValidationProblem("motionBlur.camera", "\"path\"",
                    "moves each camera towards the next camera of its split, but in a multi-view capture the cameras are a rig that stands still over time.",
                    "Use \"still\" (only the content blurs) or \"shake\"."));
            return problems;
        }
    }
}
