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

        Scratch(string root, bool owned)
        {
            Root = root;
            _owned = owned;
        }

        readonly bool _owned = true;

        /// <summary>A view of an existing folder (inside another scratch folder, which deletes it).</summary>
        public static Scratch In(string root) => new Scratch(root, false);

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
            if (_owned && Directory.Exists(Root)) Directory.Delete(Root, true);
        }
    }
}
