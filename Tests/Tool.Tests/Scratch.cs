using System;
using System.IO;

namespace NerfDatasetCreator.Tool.Tests
{
    /// <summary>A temp folder deleted after the test.</summary>
    sealed class Scratch : IDisposable
    {
        public Scratch()
        {
            Root = Path.Combine(Path.GetTempPath(), "nerf-tool-tests-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(Root);
        }

        public string Root { get; }

        public string PathOf(params string[] parts) => Path.Combine(Root, Path.Combine(parts));

        public string WriteText(string name, string text)
        {
            var path = PathOf(name);
            File.WriteAllText(path, text);
            return path;
        }

        public void Dispose()
        {
            if (Directory.Exists(Root)) Directory.Delete(Root, true);
        }
    }
}
