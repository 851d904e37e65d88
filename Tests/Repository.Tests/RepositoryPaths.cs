using System;
using System.IO;

namespace NerfDatasetCreator.Repository.Tests
{
    static class RepositoryPaths
    {
        /// <summary>The repository root: the first ancestor of the test binary that holds package.json and ProjectSettings/.</summary>
        public static string Root
        {
            get
            {
                var dir = new DirectoryInfo(AppContext.BaseDirectory);
                while (dir != null)
                {
                    if (File.Exists(Path.Combine(dir.FullName, "package.json")) &&
                        Directory.Exists(Path.Combine(dir.FullName, "ProjectSettings")))
                        return dir.FullName;
                    dir = dir.Parent;
                }
                throw new InvalidOperationException("Repository root not found above " + AppContext.BaseDirectory);
            }
        }

        public static string PluginFolder => Path.Combine(Root, "Assets", "NeRFDatasetCreator");

        public static string Combine(params string[] parts) => Path.Combine(Root, Path.Combine(parts));
    }
}
