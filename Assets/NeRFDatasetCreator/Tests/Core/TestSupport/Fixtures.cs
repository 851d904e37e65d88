using System.IO;
using System.Runtime.CompilerServices;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// Finds fixture files next to the test sources. [CallerFilePath] is the path the compiler was given for this
    /// file — relative to the project folder (Unity's working directory) in Unity, absolute under dotnet — so this
    /// works in both without TestContext.CurrentContext.TestDirectory.
    /// </summary>
    static class Fixtures
    {
        public static string Path(string relativePath)
        {
            var testSupport = System.IO.Path.GetDirectoryName(ThisFile());
            var testsCore = Directory.GetParent(testSupport).FullName;
            var path = System.IO.Path.Combine(testsCore, "Fixtures", relativePath);
            if (!File.Exists(path))
                throw new FileNotFoundException("Test fixture not found (looked next to the test sources): " + path, path);
            return path;
        }

        public static string LegoTrainTransforms => Path(System.IO.Path.Combine("nerf_synthetic_lego", "transforms_train.json"));

        static string ThisFile([CallerFilePath] string path = "") => path;
    }
}
