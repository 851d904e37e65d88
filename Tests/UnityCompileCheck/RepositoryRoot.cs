using System;
using System.IO;

namespace NerfDatasetCreator.UnityCompileCheck
{
    static class RepositoryRoot
    {
        /// <summary>The first ancestor of the test binary that holds package.json and ProjectSettings/.</summary>
        public static string Path
        {
            get
            {
                var dir = new DirectoryInfo(AppContext.BaseDirectory);
                while (dir != null)
                {
                    if (File.Exists(System.IO.Path.Combine(dir.FullName, "package.json")) &&
                        Directory.Exists(System.IO.Path.Combine(dir.FullName, "ProjectSettings")))
                        return dir.FullName;
                    dir = dir.Parent;
                }
                throw new InvalidOperationException("Repository root not found above " + AppContext.BaseDirectory);
            }
        }
    }
}
