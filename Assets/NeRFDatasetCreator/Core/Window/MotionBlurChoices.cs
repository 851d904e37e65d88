using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What the window's Motion blur section (step 5, Outputs; Documentation~/motion-blur.md) shows for a
    /// <see cref="MotionBlurSettings"/>: the camera-motion popup and the fields the validator reports under.
    /// </summary>
    public static class MotionBlurChoices
    {
        /// <summary>The camera popup's labels, in <see cref="ShutterCameraMotion"/> order; each starts with its config name.</summary>
        public static readonly string[] CameraLabels =
        {
            "Path (along the split's cameras)",
            "Shake (seeded per view)",
            "Still (only the content moves)",
        };

        /// <summary>The camera popup's tooltips, in <see cref="ShutterCameraMotion"/> order.</summary>
        public static readonly string[] CameraTooltips =
        {
            "The camera moves towards its neighbours in the split's order (formation, imported file, animated camera) over the shutter. " +
            "For formations whose consecutive views are far apart (sphere, random) use Shake.",
            "A seeded random move of Shake distance and turn of Shake angle per view.",
            "The camera stands still; only the content of a dynamic capture (step 4) moves.",
        };

        /// <summary>"motionBlur.shutter" and the like: the field the validator reports a setting under.</summary>
        public static string Field(string key) => MotionBlurSettingsJson.Key + "." + key;

        /// <summary>The fields the section draws for these settings, in its order (the shake's only for a shake).</summary>
        public static string[] Shown(MotionBlurSettings blur)
        {
            if (blur == null) throw new ArgumentNullException(nameof(blur));
            if (!blur.Enabled) return Array.Empty<string>();
            return blur.Camera == ShutterCameraMotion.Shake
                ? new[] { Field("camera"), Field("shakeDistance"), Field("shakeDegrees"), Field("shutter"), Field("subFrames"), Field("readout") }
                : new[] { Field("camera"), Field("shutter"), Field("subFrames"), Field("readout") };
        }
    }
}
