using System;
using System.IO;

namespace NerfDatasetCreator.Tests
{
    /// <summary>A fresh folder under the system temp folder, deleted with everything in it on Dispose.</summary>
    sealed class TempFolder : IDisposable
    {
        public TempFolder()
        {
            Path = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "nerf-tests-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(Path);
        }

        public string Path { get; }

        public string Combine(params string[] parts) => System.IO.Path.Combine(Path, System.IO.Path.Combine(parts));

        public void Dispose()
        {
            if (!Directory.Exists(Path)) return;
            // Tests make folders read-only to simulate write errors; undo that so cleanup works.
            foreach (var dir in Directory.GetDirectories(Path, "*", SearchOption.AllDirectories))
                new DirectoryInfo(dir).Attributes = FileAttributes.Normal;
            Directory.Delete(Path, true);
        }
    }
}
