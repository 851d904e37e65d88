using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>nerf-dataset place-splat</c> and the Editor's <i>Place trained splat</i>: finds the trained model's PLY, detects
    /// its trainer, composes the trainer's frame with the dataset's <c>unity_frame</c>, and writes the viewer's
    /// <c>cameras.json</c> (issue 34). The splat is placed, never rewritten: aras-p's renderer takes centres through the
    /// object-to-world matrix and the SH view direction through its inverse, so a reflecting transform renders correctly
    /// (sources in Documentation~/maintainers/splat-placement.md).
    /// </summary>
    public static class SplatPlacer
    {
        /// <param name="datasetDir">The dataset folder (<c>dataset_config.json</c> and the transforms files).</param>
        /// <param name="model">The trained output: a 3DGS model folder, a nerfstudio run folder, a gsplat result folder.</param>
        /// <param name="trainer">"3dgs", "nerfstudio", "gsplat", or null to detect it from the folder.</param>
        /// <param name="ply">The PLY to place when the trainer wrote it elsewhere (nerfstudio's <c>ns-export --output-dir</c>), or null.</param>
        /// <param name="writeCameras">Write a 3DGS-format cameras.json where the viewer finds it (never over an existing file).</param>
        public static SplatPlacement Place(string datasetDir, string model, string trainer = null, string ply = null, bool writeCameras = true)
        {
            var frame = ReadFrame(datasetDir);
            var trained = TrainedModel.Find(model, trainer, ply);
            var notes = new List<string>();
            if (frame.Derived) notes.Add("the dataset has no unity_frame (written before it existed): the way back to Unity is derived from " + frame.DerivedFrom + ".");
            notes.AddRange(trained.Notes);
            var objectToWorld = frame.OutputToUnity * trained.TrainerToOutput;
            var transform = UnityTransform.FromMatrix(objectToWorld);
            if (transform.Shear > 1e-9)
                notes.Add("the map is not a similarity (columns " + transform.Shear.ToString("0.###e0", System.Globalization.CultureInfo.InvariantCulture) + " from orthogonal): the Transform shows it only approximately; object_to_world is exact.");

            string written = null;
            var cameraCount = 0;
            if (writeCameras)
            {
                var target = Path.Combine(Path.GetDirectoryName(trained.PlyPath), SplatCamerasJson.FileName);
                if (File.Exists(target))
                    notes.Add("cameras.json not written: " + target + " exists and is never replaced.");
                else
                {
                    var cameras = SplatCamerasJson.Build(datasetDir, trained.OutputToTrainer);
                    try
                    {
                        AtomicFile.WriteNewText(target, ExportJson.Serialise(cameras) + "\n");
                        written = target;
                        cameraCount = cameras.Count;
                    }
                    catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
                    {
                        notes.Add("cameras.json not written to " + target + ": " + e.Message);
                    }
                }
            }
            var viewerReads = SplatCamerasJson.ViewerWillRead(trained.PlyPath);
            return new SplatPlacement(trained.Trainer, trained.PlyPath, AffineMaps.RowMajor(objectToWorld),
                new[] { transform.Position.X, transform.Position.Y, transform.Position.Z },
                new[] { transform.Rotation.X, transform.Rotation.Y, transform.Rotation.Z, transform.Rotation.W },
                new[] { transform.Scale.X, transform.Scale.Y, transform.Scale.Z }, written, notes)
            {
                EulerDegrees = new[] { transform.EulerDegrees.X, transform.EulerDegrees.Y, transform.EulerDegrees.Z },
                TrainerFrame = trained.Frame,
                TrainerToOutput = AffineMaps.RowMajor(trained.TrainerToOutput),
                OutputToUnity = AffineMaps.RowMajor(frame.OutputToUnity),
                UnityFrameDerivedFrom = frame.DerivedFrom,
                ViewerCamerasJsonPath = viewerReads,
                CameraCount = cameraCount,
            };
        }

        /// <summary>
        /// The dataset's <see cref="UnityFrameRecord"/>: from dataset_config.json, else transforms_train.json, else a
        /// converted nerfstudio transforms.json (convert carries <c>unity_frame</c> there): the first file recording
        /// <c>unity_frame</c> or <c>scene_normalisation</c>. Refused, naming the files, when none does.
        /// </summary>
        public static UnityFrameRecord ReadFrame(string datasetDir)
        {
            if (string.IsNullOrWhiteSpace(datasetDir) || !Directory.Exists(datasetDir))
                throw TrainedModel.Refuse("dataset", datasetDir ?? "(missing)", "is not an existing folder.", "Pass the dataset folder (dataset_config.json and the transforms files).");
            var root = Path.GetFullPath(datasetDir);
            var config = DatasetConfig.Read(root);
            if (config.State != DatasetConfigState.Read && config.State != DatasetConfigState.Missing)
                throw TrainedModel.Refuse(DatasetLayout.ConfigFileName, config.Path, "cannot be read: " + config.Error, "Restore the file from the capture, or capture again.");
            var frame = UnityFrameRecord.Read(config.Config?.Json);
            foreach (var name in new[] { DatasetLayout.TransformsFileName("train"), "transforms.json" })
            {
                if (frame != null) break;
                var path = Path.Combine(root, name);
                if (!File.Exists(path)) continue;
                try { frame = UnityFrameRecord.Read(Newtonsoft.Json.Linq.JObject.Parse(FileOps.ReadText(path)), name); }
                catch (Newtonsoft.Json.JsonException e) { throw TrainedModel.Refuse(name, path, "is not valid JSON: " + e.Message, "Restore the file, or capture again."); }
            }
            if (frame == null)
                throw TrainedModel.Refuse("dataset", root, "records no way back to Unity: no unity_frame or scene_normalisation in " + DatasetLayout.ConfigFileName + ", transforms_train.json or transforms.json.",
                    "Pass a dataset this plugin wrote (its dataset_config.json records the frame).");
            return frame;
        }
    }
}
