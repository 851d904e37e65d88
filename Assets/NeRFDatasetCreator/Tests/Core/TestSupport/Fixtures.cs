using System.IO;
using System.Runtime.CompilerServices;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Files in Tests/Core/Fixtures, found from this source file's path. [CallerFilePath] is the path the compiler was
    /// given — relative to the project folder (Unity's working directory) in Unity, absolute under dotnet — so this
    /// works in both without TestContext.CurrentContext.TestDirectory.
    /// </summary>
    static class Fixtures
    {
        static string TestSupportFolder([CallerFilePath] string path = "") => Path.GetDirectoryName(path);

        public static string Folder => Path.Combine(Path.GetDirectoryName(TestSupportFolder()), "Fixtures");

        public static string PathOf(params string[] parts) => Path.Combine(Folder, Path.Combine(parts));

        public static string Text(params string[] parts) => File.ReadAllText(PathOf(parts));

        /// <summary>nerf_synthetic's lego transforms_train.json (the NeRF authors' data, CC BY 3.0).</summary>
        public static string LegoTrainPath => PathOf("nerf_synthetic_lego", "transforms_train.json");
    }
}
