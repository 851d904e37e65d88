using System;
using System.IO;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What a path given to <c>validate</c> or <c>check</c> is when it is not a Blender-format dataset folder, in one
    /// sentence with what to do (issue 33: a file was "a folder that does not exist", an export was three missing
    /// transforms files): a file; a missing folder whose capture has not finished; the working folder of a capture or
    /// plan still running or stopped (<see cref="WorkingFolders"/>); an export of <c>convert</c> (nerfstudio,
    /// instant-ngp, COLMAP / 3DGS, Gaussian Grouping, Dynamic 3D Gaussians), recognised by the files each writes.
    /// Null for a folder with a transforms_&lt;split&gt;.json, or one it does not recognise (the validator's own
    /// problems then say what is missing).
    /// </summary>
    public static class NotADatasetFolder
    {
        /// <summary>The sentence, to follow the path as given ("&lt;path&gt;: is a file, not a folder: …"), or null.</summary>
        public static string Describe(string path)
        {
            if (string.IsNullOrEmpty(path)) return null;
            var full = Path.GetFullPath(path);
            if (File.Exists(full)) return AFile(full);
            if (!Directory.Exists(full)) return Missing(full);
            var working = WorkingFolders.KindOf(Path.GetFileName(full.TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar)));
            if (working != null) return HalfWritten(full, working);
            if (DatasetSplits.All.Any(s => File.Exists(Path.Combine(full, DatasetLayout.TransformsFileName(s))))) return null;
            return Export(full);
        }

        static string AFile(string file)
        {
            var folder = Path.GetDirectoryName(file);
            var name = Path.GetFileName(file);
            var inDataset = name.StartsWith("transforms", StringComparison.OrdinalIgnoreCase) || name == DatasetLayout.ConfigFileName;
            return "is a file, not a folder: pass the dataset folder that holds transforms_train.json" + (inDataset ? " (here " + folder + ")." : ".");
        }

        static string Missing(string folder)
        {
            var partial = WorkingFolders.Of(folder).FirstOrDefault(w => WorkingFolders.KindOf(Path.GetFileName(w)) == "write");
            if (partial == null) return "does not exist. Pass the dataset folder that holds transforms_train.json.";
            return "does not exist yet: a capture or plan into it has not finished, and " + partial + " holds its files so far. " + RunningOrStopped(partial);
        }

        static string HalfWritten(string folder, string kind)
        {
            var output = WorkingFolders.OutputOf(folder);
            var what = kind == "convert" ? "a convert" : kind == "merge" ? "a merge" : kind == "replaced" ? "the dataset a replacing capture moved aside" : "a capture or plan";
            return "is the working folder of " + what + " into " + output + ", not a dataset. " + RunningOrStopped(folder);
        }

        /// <summary>Whether the run that writes <paramref name="working"/> may still be running (its journal's owner), and what to do either way.</summary>
        static string RunningOrStopped(string working)
        {
            var journal = OperationJournal.Load(working);
            var running = journal == null ? null : OperationOwner.WhyMayBeRunning(journal.Owner, working);
            var parent = Path.GetDirectoryName(WorkingFolders.OutputOf(working) ?? working);
            return running != null
                ? "It may still be running (" + running + "): wait for it to finish and validate the dataset folder it writes."
                : "Its run has ended without finishing (killed, crashed or cancelled): capture again, or run `nerf-dataset clean " + parent + "` to finish or remove what it left.";
        }

        static string Export(string folder)
        {
            string Has(params string[] parts) => File.Exists(Path.Combine(new[] { folder }.Concat(parts).ToArray())) ? Path.Combine(parts) : null;
            var what =
                Has(Dynamic3DGaussians.TrainMetaFileName) != null ? "a Dynamic 3D Gaussians export (train_meta.json) of nerf-dataset convert; train with Dynamic 3D Gaussians' train.py on it" :
                (Has("sparse", "0", "cameras.txt") ?? Has("sparse", "0", "cameras.bin")) != null
                    ? Directory.Exists(Path.Combine(folder, GaussianGrouping.ObjectMaskFolder))
                        ? "a Gaussian Grouping export (COLMAP model and object_mask/) of nerf-dataset convert; train with Gaussian Grouping's train.py -s " + folder
                        : "a COLMAP export (sparse/0/) of nerf-dataset convert, or a COLMAP reconstruction; train with 3D Gaussian Splatting: python train.py -s " + folder
                    : Has(NerfstudioWriter.FileName) != null ? SingleTransforms(folder) : null;
            return what == null ? null : "is " + what + ". validate and check read the Blender-format dataset it came from (transforms_train/val/test.json): pass that folder.";
        }

        /// <summary>nerfstudio's and instant-ngp's exports are both one transforms.json: told apart by their keys.</summary>
        static string SingleTransforms(string folder)
        {
            var file = Path.Combine(folder, NerfstudioWriter.FileName);
            JObject json = null;
            try
            {
                if (new FileInfo(file).Length <= FileOps.MaxTextBytes) json = JObject.Parse(FileOps.ReadText(file));
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is Newtonsoft.Json.JsonException) { }
            if (json?["train_filenames"] != null || json?["camera_model"] != null)
                return "a nerfstudio export (transforms.json with train_filenames) of nerf-dataset convert; train with ns-train nerfacto --data " + file + " nerfstudio-data";
            if (json?["aabb_scale"] != null)
                return "an instant-ngp export (transforms.json with aabb_scale) of nerf-dataset convert; train with ./instant-ngp " + file;
            return "a single transforms.json (nerfstudio's or instant-ngp's layout), not the three split files";
        }
    }
}
