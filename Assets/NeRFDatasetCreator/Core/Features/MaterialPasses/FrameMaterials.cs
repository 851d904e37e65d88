using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The material files one frame names (<see cref="MaterialKeys"/>), from its keys only: per pass the PNG the key names
    /// and the EXR beside it (the same path with <c>.exr</c>; emission's key names its EXR), and the coverage PNG. Empty for
    /// a frame without material keys.
    /// </summary>
    public sealed class FrameMaterials
    {
        /// <summary>One pass's files: <see cref="Png"/> null for emission; <see cref="Exr"/> null when the key's value does not end in the expected extension.</summary>
        public sealed class Files
        {
            public MaterialPass Pass;
            public DatasetFile Png, Exr;
        }

        public static readonly FrameMaterials None = new FrameMaterials();

        readonly List<Files> _passes = new List<Files>();

        /// <summary>The passes the frame names, in <see cref="MaterialPassFiles.All"/>'s order.</summary>
        public IReadOnlyList<Files> Passes => _passes;

        /// <summary>The coverage PNG (<c>material_coverage_path</c>), or null.</summary>
        public DatasetFile Coverage { get; private set; }

        public bool Any => _passes.Count > 0 || Coverage != null;

        /// <summary>The files of the pass named <paramref name="name"/>, or null.</summary>
        public Files Of(string name)
        {
            foreach (var files in _passes)
                if (files.Pass.Name == name) return files;
            return null;
        }

        internal static FrameMaterials Of(DatasetFrame frame)
        {
            if (frame == null) return None;
            var result = new FrameMaterials();
            foreach (var pass in MaterialPassFiles.All)
            {
                var named = frame.Named(pass.Key);
                if (named == null) continue;
                var files = new Files { Pass = pass };
                if (pass.Png == null) files.Exr = named;
                else
                {
                    files.Png = named;
                    var written = named.Written;
                    if (written.EndsWith(".png", StringComparison.OrdinalIgnoreCase) && frame.File?.Root != null)
                        files.Exr = DatasetFile.Resolve(frame.File.Root, pass.Key, written.Substring(0, written.Length - 4) + ".exr", false);
                }
                result._passes.Add(files);
            }
            result.Coverage = frame.Named(MaterialKeys.CoveragePath);
            return result;
        }
    }
}
