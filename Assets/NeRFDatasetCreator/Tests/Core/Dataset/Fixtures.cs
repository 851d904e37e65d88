using System.IO;
using System.Runtime.CompilerServices;

namespace NerfDatasetCreator.Tests
{
    /// <summary>Files in Tests/Core/Fixtures, found from this source file's path (works in Unity and under dotnet test).</summary>
    static class Fixtures
    {
        static string Here([CallerFilePath] string path = "") => Path.GetDirectoryName(path);

        public static string Folder => Path.Combine(Path.GetDirectoryName(Here()), "Fixtures");

        public static string PathOf(params string[] parts) => Path.Combine(Folder, Path.Combine(parts));

        public static string Text(params string[] parts) => File.ReadAllText(PathOf(parts));

        /// <summary>nerf_synthetic's lego transforms_train.json (the NeRF authors' data, CC BY 3.0).</summary>
        public static string LegoTrainPath => PathOf("nerf_synthetic_lego", "transforms_train.json");

        /// <summary>The repository's package.json (three folders above Tests/Core/Dataset's plugin folder).</summary>
        public static string PackageJsonPath => Path.Combine(Here(), "..", "..", "..", "..", "..", "package.json");
    }
}
