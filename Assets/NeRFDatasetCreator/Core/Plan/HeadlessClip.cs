using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// How the headless tool plans a dynamic config whose time range ends at the clip's length (<c>"end": "clip"</c>,
    /// as the bundled dynamic sample configs do), which only Unity can measure. When the number of time steps does not
    /// depend on that length (<c>time.fps</c> 0: <c>time.steps</c>, or the train count, sets it), every view's camera and
    /// normalised time are what Unity plans whatever the clip's length; only the seconds differ. So the plan assumes a
    /// clip one second past <c>time.start</c> and says so. With <c>time.fps</c> &gt; 0 the steps follow from the length,
    /// and the plan is refused as before (<see cref="TimePlanning"/>'s message).
    /// </summary>
    public static class HeadlessClip
    {
        /// <summary>The assumed length past <c>time.start</c>, in seconds.</summary>
        public const double AssumedSecondsAfterStart = 1;

        /// <summary>Whether <paramref name="settings"/> can be planned headless with an assumed clip length.</summary>
        public static bool Applies(DatasetSettings settings) =>
            settings?.Time != null && settings.Time.Enabled && settings.Time.EndAtClipLength && settings.Time.Fps == 0;

        /// <summary>The target the headless plan uses: <see cref="PlanTarget.Headless"/>, with the assumed clip when <see cref="Applies"/>.</summary>
        public static PlanTarget Target(DatasetSettings settings) =>
            Applies(settings) ? PlanTarget.HeadlessWithClip(AssumedEnd(settings)) : PlanTarget.Headless;

        public static double AssumedEnd(DatasetSettings settings) => settings.Time.StartSeconds + AssumedSecondsAfterStart;

        /// <summary>The note the plan prints with the assumption.</summary>
        public static string Note(DatasetSettings settings) =>
            "time.end = \"clip\": the clip's length is known only in Unity, which opens the scene; planned with a clip ending at " +
            AssumedEnd(settings).ToString("R", CultureInfo.InvariantCulture) + " s. The cameras, time steps and normalised times are the ones Unity plans; " +
            "the seconds (time_seconds, and dataset_config.json's time range) are the assumption's, and the capture in Unity writes the clip's own.";
    }
}
