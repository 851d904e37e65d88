using System;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Whether a folder is provably a dataset this plugin wrote, and holds nothing else — the only kind of folder
    /// <c>"overwrite": "replace"</c> may delete. Proof: a <c>dataset_config.json</c> whose <c>generator</c> is this
    /// plugin, and every entry one of the names the plugin (capture, plan, merge, convert) writes. A stray file, a
    /// foreign config or a symbolic link makes it someone else's data. A replace is stricter still
    /// (<see cref="WhyNotReplaceable"/>): it never deletes convert's exports, and a plan never deletes rendered images.
    /// </summary>
    public static class OwnDataset
    {
        static readonly Regex ViewFile = new Regex(@"^r_\d+(\.png|_depth_0000\.png|_depth_0000\.exr|_normal_0000\.png|_normal_0000\.exr|_mask_0000\.png|_instance_0000\.png|_semantic_0000\.png|_clean\.png|_sharp_0000\.png|_hdr\.exr)$", RegexOptions.CultureInvariant);
        static readonly string[] RootFiles = new[]
        {
            DatasetLayout.ConfigFileName, DatasetLayout.RigPreviewFileName, RigPreviewPicture.FileName, TargetPointCloud.FileName, ShardManifest.FileName,
            NerfstudioWriter.FileName, OperationJournal.FileName, OperationJournal.FileName + ".tmp", DatasetCheck.ReportFileName,
            DatasetLayout.LabelsFileName, EvalProtocolFile.FileName,
        }.Concat(DatasetSplits.Names.Select(DatasetLayout.LabelsPreviewFileName)).ToArray();
        static readonly string[] ColmapSparseFiles = { "cameras.txt", "images.txt", "points3D.txt", "points3D.ply", "test.txt", GaussianSplattingDepths.ParamsFileName };

        // The export folders convert writes into a dataset by default, as trees of the names each may hold.
        static readonly Tree SplitFolder = new Tree(f => ViewFile.IsMatch(f));
        static readonly Tree Png = new Tree(f => f.EndsWith(".png", StringComparison.OrdinalIgnoreCase));
        static readonly Tree GeometryPack = new Tree(GeometryPackSteps.IsPackFile);
        // flow/ (FlowLayout): the record, and per video the pair files and the tracks.
        static readonly Regex FlowFile = new Regex(@"^((flow|occluded|outside|scene_flow)_\d{4}_\d{4}\.(flo|png|exr)|tracks_\d{4}\.npz)$", RegexOptions.CultureInvariant);
        static readonly Tree Flow = new Tree(f => f == "flow.json", new Tree(f => FlowFile.IsMatch(f)));
        static readonly Tree Splits = new Tree(SparseSplit.IsFileName);
        static readonly Tree CameraPaths = new Tree(f => DatasetSplits.Names.Any(s => s + ".json" == f));
        static readonly Tree Ngp = new Tree(f => f == NgpWriter.FileName || f == EvalProtocolFile.FileName).With(CameraPathFiles.FolderName, CameraPaths);
        static readonly Tree Colmap = new Tree(f => f == EvalProtocolFile.FileName)
            .With(ColmapTextWriter.ImagesFolder, Png)
            .With("sparse", new Tree(f => false).With("0", new Tree(f => ColmapSparseFiles.Contains(f))))
            .With(GaussianSplattingDepths.FolderName, Png);
        static readonly Tree Dynamic3dgs = new Tree(f => f == EvalProtocolFile.FileName || f == Dynamic3DGaussians.TrainMetaFileName || f == Dynamic3DGaussians.TestMetaFileName || f == Dynamic3DGaussians.PointCloudFileName)
            .With(Dynamic3DGaussians.ImagesFolder, new Tree(f => false, Png))
            .With(Dynamic3DGaussians.SegmentationFolder, new Tree(f => false, Png));

        /// <summary>Null when <paramref name="folder"/> is provably this plugin's dataset and nothing else; otherwise why not.</summary>
        public static string WhyNotOurs(string folder) => Check(folder, exportsAllowed: true);

        /// <summary>
        /// Null when <c>"overwrite": "replace"</c> may delete <paramref name="folder"/> for a new dataset; otherwise the
        /// reason. Beyond <see cref="WhyNotOurs"/>: no replace deletes an export (what <c>nerf-dataset convert</c> wrote:
        /// <c>transforms.json</c>, <c>ngp/</c>, <c>colmap/</c>, <c>dynamic3dgs/</c>, <c>camera_paths/</c>) — the user made it
        /// after the capture and nothing would bring it back — and a replace that renders no images (a plan,
        /// <paramref name="rendersImages"/> false) never deletes a dataset whose images were rendered.
        /// </summary>
        public static string WhyNotReplaceable(string folder, bool rendersImages)
        {
            var why = Check(folder, exportsAllowed: false);
            if (why != null || rendersImages) return why;
            return WhyRendered(folder) is string rendered
                ? rendered + ", and a plan renders none: replacing it would throw the rendering away"
                : null;
        }

        /// <summary>Why <paramref name="folder"/> counts as rendered (its config says so, or a split folder holds an image); null when it does not.</summary>
        static string WhyRendered(string folder)
        {
            var config = DatasetConfig.Read(folder);
            if (config.State == DatasetConfigState.Unreadable || config.State == DatasetConfigState.NotJson)
                return "its " + DatasetLayout.ConfigFileName + " cannot be read (" + config.Error + ")";
            if (config.Config?.ImagesRendered == true)
                return "its " + DatasetLayout.ConfigFileName + " says its images were rendered (\"imagesRendered\": true)";
            foreach (var split in DatasetSplits.Names)
            {
                var dir = Path.Combine(folder, split);
                if (!Directory.Exists(dir)) continue;
                var image = Directory.EnumerateFiles(dir).OrderBy(f => f, StringComparer.Ordinal).FirstOrDefault();
                if (image != null) return "it holds rendered images (" + image + ")";
            }
            return null;
        }

        static string Check(string folder, bool exportsAllowed)
        {
            var config = DatasetConfig.Read(folder);
            if (config.State == DatasetConfigState.Missing) return "it has no " + DatasetLayout.ConfigFileName + ", so nothing proves this plugin wrote it";
            if (config.State == DatasetConfigState.Unreadable || config.State == DatasetConfigState.NotJson)
                return "its " + DatasetLayout.ConfigFileName + " cannot be read (" + config.Error + ")";
            if (config.Config?.IsThisPlugin != true)
                return "its " + DatasetLayout.ConfigFileName + " does not name \"" + PluginInfo.Name + "\" as its generator";
            try
            {
                return Foreign(folder, exportsAllowed);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                return "it cannot be listed (" + e.Message + ")";
            }
        }

        /// <summary>The first entry this plugin does not write (or, unless <paramref name="exportsAllowed"/>, an export), described; null when there is none.</summary>
        static string Foreign(string folder, bool exportsAllowed)
        {
            foreach (var entry in new DirectoryInfo(folder).EnumerateFileSystemInfos().OrderBy(e => e.Name, StringComparer.Ordinal))
            {
                if (IsLink(entry)) return Stray(entry) + " is a symbolic link";
                var name = entry.Name;
                if (entry is FileInfo)
                {
                    if (name == NerfstudioWriter.FileName && !exportsAllowed) return Export(entry);
                    if (RootFiles.Contains(name) || DatasetSplits.All.Any(s => DatasetLayout.TransformsFileName(s) == name)) continue;
                    return Stray(entry) + " was not written by this plugin";
                }
                string inside;
                var export = name == NgpWriter.FolderName || name == DatasetConverter.ColmapFolderName || name == Dynamic3DGaussians.FolderName ||
                             name == CameraPathFiles.FolderName || WorkingFolders.KindOf(name) == "convert";
                if (export && !exportsAllowed) return Export(entry);
                if (DatasetSplits.Names.Contains(name)) inside = SplitFolder.Foreign(entry.FullName);
                else if (name == NgpWriter.FolderName) inside = Ngp.Foreign(entry.FullName);
                else if (name == DatasetConverter.ColmapFolderName) inside = Colmap.Foreign(entry.FullName);
                else if (name == Dynamic3DGaussians.FolderName) inside = Dynamic3dgs.Foreign(entry.FullName);
                else if (name == TargetMeshPly.Folder) inside = GeometryPack.Foreign(entry.FullName);
                else if (name == FlowLayout.Folder) inside = Flow.Foreign(entry.FullName);
                else if (name == CameraPathFiles.FolderName) inside = CameraPaths.Foreign(entry.FullName);
                else if (name == SparseSplit.FolderName) inside = Splits.Foreign(entry.FullName);
                else if (WorkingFolders.KindOf(name) == "convert") continue;
                else return Stray(entry) + " was not written by this plugin";
                if (inside != null) return inside;
            }
            return null;
        }

        static string Export(FileSystemInfo entry) =>
            Stray(entry) + " is an export made with nerf-dataset convert, which a replace would delete and nothing would bring back";

        static string Stray(FileSystemInfo entry) => entry.FullName;

        /// <summary>The names a folder may hold: files <c>accept</c>s, the named sub-folders, and any other sub-folder if <c>anyFolder</c> is given.</summary>
        sealed class Tree
        {
            readonly Func<string, bool> _files;
            readonly Tree _anyFolder;
            readonly System.Collections.Generic.Dictionary<string, Tree> _folders = new System.Collections.Generic.Dictionary<string, Tree>(StringComparer.Ordinal);

            public Tree(Func<string, bool> files, Tree anyFolder = null)
            {
                _files = files;
                _anyFolder = anyFolder;
            }

            public Tree With(string folder, Tree tree)
            {
                _folders[folder] = tree;
                return this;
            }

            /// <summary>The first entry under <paramref name="folder"/> this tree does not allow, described; null when there is none.</summary>
            public string Foreign(string folder)
            {
                foreach (var entry in new DirectoryInfo(folder).EnumerateFileSystemInfos())
                {
                    if (IsLink(entry)) return Stray(entry) + " is a symbolic link";
                    if (entry is FileInfo)
                    {
                        if (!_files(entry.Name)) return Stray(entry) + " was not written by this plugin";
                        continue;
                    }
                    var sub = _folders.TryGetValue(entry.Name, out var named) ? named : _anyFolder;
                    if (sub == null) return Stray(entry) + " was not written by this plugin";
                    var inside = sub.Foreign(entry.FullName);
                    if (inside != null) return inside;
                }
                return null;
            }
        }

        /// <summary>A symbolic link (or Windows junction): .NET and Mono both report it as a reparse point.</summary>
        public static bool IsLink(FileSystemInfo entry) => (entry.Attributes & FileAttributes.ReparsePoint) != 0;
    }
}
