namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Which of the window's steps are open, per step, for the editor session: SessionState keeps a value across
    /// script reloads and clears it when Unity exits (https://docs.unity3d.com/2022.3/Documentation/ScriptReference/SessionState.html),
    /// so every session starts with all steps open and nothing is written into the project or shared between
    /// projects as EditorPrefs would be.
    /// </summary>
    public static class WindowStepFoldouts
    {
        /// <summary>The SessionState key of a step, e.g. <c>NerfDatasetCreator.Window.Step3.Open</c>.</summary>
        public static string Key(WindowStep step) => "NerfDatasetCreator.Window.Step" + (int)step + ".Open";

        public static bool IsOpen(WindowStep step) => UnityEditor.SessionState.GetBool(Key(step), true);

        public static void SetOpen(WindowStep step, bool open) => UnityEditor.SessionState.SetBool(Key(step), open);
    }
}
