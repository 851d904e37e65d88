using System;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Whether a folder is provably a dataset this plugin wrote, and holds nothing else — the only kind of folder
    /// <c>"overwrite": "replace"</c> may delete. Proof: a <c>dataset_config.json</c> whose <c>generator</c> is this
    /// plugin, and every entry one of the names the plugin (capture, plan, merge, convert) writes. A stray file, a
    /// foreign config or a symbolic link makes it someone else's data.
    /// </summary>
    public static class OwnDataset
    {
        static readonly Regex ViewFile = new Regex(@"^r_\d+(\.png|_depth_0000\.png|_depth_0000\.exr|_normal_0000\.png|_normal_0000\.exr|_mask_0000\.png)$", RegexOptions.CultureInvariant);
        static readonly string[] RootFiles =
        {
            DatasetLayout.ConfigFileName, DatasetLayout.RigPreviewFileName, TargetPointCloud.FileName, ShardManifest.FileName,
            NerfstudioWriter.FileName, OperationJournal.FileName, OperationJournal.FileName + ".tmp",
        };
        static readonly string[] ColmapSparseFiles = { "cameras.txt", "images.txt", "points3D.txt", "points3D.ply", "test.txt" };

        /// <summary>Null when <paramref name="folder"/> is provably this plugin's dataset and nothing else; otherwise why not.</summary>
        public static string WhyNotOurs(string folder)
        {
            var config = Path.Combine(folder, DatasetLayout.ConfigFileName);
            if (!File.Exists(config)) return "it has no " + DatasetLayout.ConfigFileName + ", so nothing proves this plugin wrote it";
            try
            {
                var json = JToken.Parse(FileOps.ReadText(config)) as JObject;
                if (json == null || json["generator"]?.Type != JTokenType.String || (string)json["generator"] != PluginInfo.Name)
                    return "its " + DatasetLayout.ConfigFileName + " does not name \"" + PluginInfo.Name + "\" as its generator";
            }
            catch (Exception e) when (e is JsonException || e is IOException || e is UnauthorizedAccessException)
            {
                return "its " + DatasetLayout.ConfigFileName + " cannot be read (" + e.Message + ")";
            }
            try
            {
                return Foreign(folder);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                return "it cannot be listed (" + e.Message + ")";
            }
        }

        /// <summary>The first entry this plugin does not write, described; null when there is none.</summary>
        static string Foreign(string folder)
        {
            foreach (var entry in new DirectoryInfo(folder).EnumerateFileSystemInfos().OrderBy(e => e.Name, StringComparer.Ordinal))
            {
                if (IsLink(entry)) return Stray(entry) + " is a symbolic link";
                var name = entry.Name;
                if (entry is FileInfo)
                {
                    if (RootFiles.Contains(name) || DatasetSplits.All.Any(s => DatasetLayout.TransformsFileName(s) == name)) continue;
                    return Stray(entry) + " was not written by this plugin";
                }
                string inside;
                if (DatasetSplits.Names.Contains(name)) inside = Only(entry.FullName, f => ViewFile.IsMatch(f));
                else if (name == NgpWriter.FolderName) inside = Only(entry.FullName, f => f == NgpWriter.FileName);
                else if (name == DatasetConverter.ColmapFolderName) inside = Colmap(entry.FullName);
                else if (WorkingFolders.KindOf(name) == "convert") continue;
                else return Stray(entry) + " was not written by this plugin";
                if (inside != null) return inside;
            }
            return null;
        }

        static string Colmap(string folder)
        {
            foreach (var entry in new DirectoryInfo(folder).EnumerateFileSystemInfos())
            {
                if (IsLink(entry)) return Stray(entry) + " is a symbolic link";
                if (entry is DirectoryInfo && entry.Name == ColmapTextWriter.ImagesFolder)
                {
                    var bad = Only(entry.FullName, f => f.EndsWith(".png", StringComparison.OrdinalIgnoreCase));
                    if (bad != null) return bad;
                }
                else if (entry is DirectoryInfo && entry.Name == "sparse")
                {
                    foreach (var sub in new DirectoryInfo(entry.FullName).EnumerateFileSystemInfos())
                    {
                        if (IsLink(sub)) return Stray(sub) + " is a symbolic link";
                        if (!(sub is DirectoryInfo) || sub.Name != "0") return Stray(sub) + " was not written by this plugin";
                        var bad = Only(sub.FullName, f => ColmapSparseFiles.Contains(f));
                        if (bad != null) return bad;
                    }
                }
                else return Stray(entry) + " was not written by this plugin";
            }
            return null;
        }

        /// <summary>Null when <paramref name="folder"/> holds only files whose names <paramref name="accept"/> accepts.</summary>
        static string Only(string folder, Func<string, bool> accept)
        {
            foreach (var entry in new DirectoryInfo(folder).EnumerateFileSystemInfos())
            {
                if (IsLink(entry)) return Stray(entry) + " is a symbolic link";
                if (!(entry is FileInfo) || !accept(entry.Name)) return Stray(entry) + " was not written by this plugin";
            }
            return null;
        }

        static string Stray(FileSystemInfo entry) => entry.FullName;

        /// <summary>A symbolic link (or Windows junction): .NET and Mono both report it as a reparse point.</summary>
        public static bool IsLink(FileSystemInfo entry) => (entry.Attributes & FileAttributes.ReparsePoint) != 0;
    }
}
