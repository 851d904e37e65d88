using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The dataset files an export's JSON names, and the path it writes for each (<see cref="ExportImages"/>): with
    /// copy or link, a file outside the export is placed in it under its dataset path (<c>train/r_0.png</c>), so the
    /// JSON's paths are the dataset's own; with relative, the path leads back into the dataset. A file already inside
    /// the export (the masks of <c>--object</c>) is named where it is. <see cref="Place"/> then copies or links the files.
    /// </summary>
    public sealed class ExportFileReferences
    {
        readonly string _root;
        readonly string _outDir;
        readonly Dictionary<string, string> _placed = new Dictionary<string, string>(System.StringComparer.Ordinal);

        public ExportFileReferences(ExportImages mode, string datasetRoot, string outDir)
        {
            Mode = mode;
            _root = Path.GetFullPath(datasetRoot);
            _outDir = Path.GetFullPath(outDir);
        }

        public ExportImages Mode { get; }

        /// <summary>How many dataset files the JSON names from outside the export (relative) or placed into it (copy, link).</summary>
        public int Count => _placed.Count;

        /// <summary>After <see cref="Place"/>: how many files were hard-linked (the rest of <see cref="Count"/> were copied).</summary>
        public int Linked { get; private set; }

        /// <summary>The path the JSON writes for <paramref name="rootRelativePath"/> (relative to the export folder, forward slashes).</summary>
        public string Reference(string rootRelativePath)
        {
            var source = Path.GetFullPath(Path.Combine(_root, rootRelativePath));
            if (ExportImagesModes.IsInside(source, _outDir)) return ExportPaths.RelativeTo(_outDir, _root, rootRelativePath);
            var inDataset = Path.GetRelativePath(_root, source);
            // A file outside the dataset itself (PathSafety refuses them; kept for safety) is never copied: named where it is.
            if (Mode == ExportImages.Relative || inDataset.StartsWith("..", System.StringComparison.Ordinal) || Path.IsPathRooted(inDataset))
            {
                _placed[source] = null;
                return ExportPaths.RelativeTo(_outDir, _root, rootRelativePath);
            }
            var destination = Path.Combine(_outDir, inDataset);
            _placed[source] = destination;
            return inDataset.Replace('\\', '/');
        }

        /// <summary>The destinations of the files to copy or link, for the never-overwrite check before anything is written.</summary>
        public IEnumerable<string> Destinations => _placed.Values.Where(d => d != null);

        /// <summary>Copies or hard-links every named file into the export; returns the files written.</summary>
        public IReadOnlyList<string> Place(StagedOutput staged)
        {
            var written = new List<string>();
            foreach (var pair in _placed)
            {
                if (pair.Value == null) continue;
                if (Mode == ExportImages.Link)
                {
                    if (staged.LinkOrCopy(pair.Key, pair.Value)) Linked++;
                }
                else staged.Copy(pair.Key, pair.Value);
                written.Add(pair.Value);
            }
            return written;
        }

        /// <summary>What the export depends on, for the command's output.</summary>
        public string Describe()
        {
            if (Count == 0) return "every file the export names is inside its folder";
            switch (Mode)
            {
                case ExportImages.Relative:
                    return "the export names " + Count + " files of the dataset by relative path (e.g. " + ExportPaths.RelativeTo(_outDir, _root, Path.GetRelativePath(_root, _placed.Keys.First())) +
                           "): it works only beside " + _root + " (--images copy makes a self-contained folder)";
                case ExportImages.Link:
                    return "the export holds its " + Count + " files: " + Linked + " hard-linked to the dataset's (no extra disk space; editing one in place edits both)" +
                           (Linked < Count ? ", " + (Count - Linked) + " copied where the file system cannot link" : "") + "; a self-contained folder";
                default:
                    return "the export holds copies of its " + Count + " files: a self-contained folder";
            }
        }
    }
}
