using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Writes each non-empty split's camera path next to an export, in <c>camera_paths/&lt;split&gt;.json</c>: the folder
    /// nerfstudio's viewer keeps its own paths in (viewer/render_panel.py, <c>datapath / "camera_paths"</c>), and a
    /// subfolder instant-ngp does not read as training data (it loads only the <c>*.json</c> files directly in a folder,
    /// testbed_nerf.cu <c>load_nerf</c> lines 2448–2453). Existing files are never overwritten.
    /// </summary>
    public static class CameraPathFiles
    {
        public const string FolderName = "camera_paths";

        /// <param name="staged">The convert's working output: files go there and are moved into place with the rest.</param>
        public static IReadOnlyList<string> Write(ExportScene scene, string outDir, ExportTarget target, ICollection<ValidationProblem> warnings, StagedOutput staged)
        {
            var written = new List<string>();
            if (target != ExportTarget.Nerfstudio && target != ExportTarget.Ngp) return written;
            if (target == ExportTarget.Nerfstudio)
                foreach (var w in NerfstudioCameraPath.Warnings(scene.Intrinsics)) warnings?.Add(w);
            var folder = Path.Combine(outDir, FolderName);
            foreach (var split in DatasetSplits.Names)
            {
                var frames = scene.Split(split).ToList();
                var poses = frames.Select(f => f.CameraToWorld).ToList();
                if (poses.Count == 0) continue;
                // A dynamic capture's times go into nerfstudio's path as render_time; instant-ngp's path has no time
                // (convert already warns that the ngp export holds none).
                var json = target == ExportTarget.Nerfstudio
                    ? NerfstudioCameraPath.Build(poses, scene.Intrinsics, times: frames.Select(f => f.Time).ToList())
                    : NgpCameraPath.Build(poses, scene.Intrinsics);
                var file = Path.Combine(folder, split + ".json");
                // Checked here, before anything is placed: found only at the move, it would leave a half-placed export.
                DatasetConverter.EnsureAbsent(file);
                staged.WriteNewText(file, ExportJson.Serialise(json));
                written.Add(file);
            }
            return written;
        }
    }
}
