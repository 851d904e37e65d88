using System.Globalization;
using System.Text.RegularExpressions;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The per-time-step geometry pack of a dynamic capture (<c>"geometryPack": "everyStep"</c>): step k's mesh is
    /// <c>geometry/target_mesh_t&lt;kkkk&gt;.ply</c> (four digits or more, zero-padded, like the views' <c>_0000</c>
    /// suffixes), written as <see cref="TargetMeshPly"/> at the content time of step k — the time of the train views
    /// whose <c>time_step</c> is k — and listed under <c>geometry.steps</c> in dataset_config.json.
    /// </summary>
    public static class GeometryPackSteps
    {
        /// <summary>The settings value that asks for every step: <c>"geometryPack": "everyStep"</c>.</summary>
        public const string EveryStepValue = "everyStep";

        public const string FilePrefix = "target_mesh_t";

        static readonly Regex StepFile = new Regex(@"^" + FilePrefix + @"(\d{4,})\.ply$", RegexOptions.CultureInvariant);

        public static string FileName(int step) => FilePrefix + step.ToString("0000", CultureInfo.InvariantCulture) + ".ply";

        public static string RelativePath(int step) => TargetMeshPly.Folder + "/" + FileName(step);

        /// <summary>Whether <paramref name="name"/> (a file name, no folder) is a step mesh's name.</summary>
        public static bool IsStepFile(string name) => name != null && StepFile.IsMatch(name);

        /// <summary>Whether <paramref name="name"/> is any geometry pack file name: <c>target_mesh.ply</c> or a step's.</summary>
        public static bool IsPackFile(string name) => name == TargetMeshPly.FileName || IsStepFile(name);
    }
}
