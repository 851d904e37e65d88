using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Threading.Tasks;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The Dataset Tools window's <i>Place trained splat</i> (issue 34): the trained output of a dataset (and an optional PLY
    /// and trainer) in, <see cref="SplatPlacer.Place"/> run on a worker (<see cref="BackgroundJob"/>; Core only), the transform
    /// shown; with a splat viewer installed (<see cref="SplatViewers"/>) a GameObject rendering the splat is placed under the
    /// source object's parent. Then <i>Show source / Show splat</i> and <i>View from camera i</i> compare them.
    /// </summary>
    [Serializable]
    public sealed class PlaceSplatSection
    {
        [SerializeField] string modelFolder = "";
        [SerializeField] string plyFile = "";
        [SerializeField] int trainer;
        [SerializeField] GameObject source;
        [SerializeField] GameObject placed;
        [SerializeField] int cameraIndex;
        [SerializeField] List<string> lines = new List<string>();
        [SerializeField] bool failed;

        static bool s_running;
        string _datasetFolder;
        ImportedPoses _cameras;
        string _camerasFrom;

        /// <summary>What the last Place or View printed; Place's refusals name the field and the fix.</summary>
        public IReadOnlyList<string> Lines => lines;
        public bool Failed => failed;
        /// <summary>The splat object the last Place made or reused (null without a viewer).</summary>
        public GameObject Placed { get => placed; set => placed = value; }

        public GameObject Source { get => source; set => source = value; }

        /// <summary>Draws the section; <paramref name="datasetFolder"/> is the window's dataset.</summary>
        public void Draw(EditorWindow host, string datasetFolder, Func<string, string, string, Action<string>, string> folderField)
        {
            EditorGUILayout.LabelField("Place trained splat", EditorStyles.boldLabel);
            modelFolder = folderField("Trained output", modelFolder,
                "A 3DGS model folder (point_cloud/iteration_N), a nerfstudio run folder (config.yml, dataparser_transforms.json) or a gsplat result folder.",
                f => modelFolder = f);
            plyFile = EditorGUILayout.TextField(new GUIContent("PLY (optional)", "The splat PLY when the trainer wrote it elsewhere (nerfstudio's ns-export --output-dir)."), plyFile ?? "");
            trainer = EditorGUILayout.Popup(new GUIContent("Trainer", "auto: detected from the folder's files."), trainer, SplatTrainerChoice.Names);
            source = (GameObject)EditorGUILayout.ObjectField(new GUIContent("Source object", "The captured target: the splat goes under its parent, and the toggle swaps the two."), source, typeof(GameObject), true);
            var viewer = SplatViewers.Installed;
            EditorGUILayout.LabelField(" ", viewer != null ? "Viewer: " + viewer.Name : "No splat viewer installed: the transform is shown only.", EditorStyles.wordWrappedMiniLabel);
            using (new EditorGUI.DisabledScope(s_running || string.IsNullOrWhiteSpace(datasetFolder) || string.IsNullOrWhiteSpace(modelFolder)))
                if (GUILayout.Button(new GUIContent(s_running ? "Placing…" : "Place", "Finds the PLY, composes the trainer's frame with the dataset's and places the splat on its source.")))
                {
                    string dataset = datasetFolder, model = modelFolder, trainerName = SplatTrainerChoice.Argument(trainer);
                    var ply = string.IsNullOrWhiteSpace(plyFile) ? null : plyFile;
                    // After this GUI event, as the window's commands run: the job changes what the window draws.
                    EditorApplication.delayCall += () => Place(host, dataset, model, trainerName, ply);
                }

            EditorGUILayout.BeginHorizontal();
            using (new EditorGUI.DisabledScope(source == null || placed == null))
            {
                var showingSplat = placed != null && placed.activeSelf && (source == null || !source.activeSelf);
                if (GUILayout.Button(new GUIContent(showingSplat ? "Show source" : "Show splat", "Shows the source or the splat, the other hidden (undoable).")))
                    ShowSplat(!showingSplat);
            }
            using (new EditorGUI.DisabledScope(string.IsNullOrWhiteSpace(datasetFolder)))
            {
                cameraIndex = Math.Max(0, EditorGUILayout.IntField(new GUIContent("Camera", "A train camera of the dataset (ids as in cameras.json)."), cameraIndex, GUILayout.Width(220)));
                if (GUILayout.Button(new GUIContent("View from camera " + cameraIndex, "Aligns the Scene view to this dataset camera with its field of view.")))
                    ViewFromCamera(datasetFolder, cameraIndex);
            }
            EditorGUILayout.EndHorizontal();
            if (lines.Count > 0)
                EditorGUILayout.HelpBox(string.Join("\n", lines), failed ? MessageType.Error : MessageType.Info);
        }

        /// <summary>Runs <see cref="SplatPlacer.Place"/> on a worker, then places the splat on the main thread.</summary>
        public void Place(EditorWindow host, string datasetFolder, string model, string trainerName, string ply)
        {
            if (s_running) return;
            s_running = true;
            _datasetFolder = datasetFolder;
            BackgroundJob.Start("NeRF dataset: place trained splat", model, reportsSteps: false, cancellable: false,
                (report, cancel) => SplatPlacer.Place(datasetFolder, model, trainerName, ply, writeCameras: true),
                task =>
                {
                    s_running = false;
                    var status = Finish(task);
                    if (host != null) host.Repaint();
                    return status;
                });
        }

        /// <summary>The same as Place, on the calling thread (tests, and callers that already run on a worker's result).</summary>
        public void PlaceNow(string datasetFolder, string model, string trainerName, string ply)
        {
            _datasetFolder = datasetFolder;
            var outcome = new TaskCompletionSource<SplatPlacement>();
            try { outcome.SetResult(SplatPlacer.Place(datasetFolder, model, trainerName, ply, writeCameras: true)); }
            catch (Exception e) { outcome.SetException(e); }
            Finish(outcome.Task);
        }

        Progress.Status Finish(Task<SplatPlacement> task)
        {
            if (task.Status != TaskStatus.RanToCompletion)
            {
                Show(true, Refusal(task.Exception?.GetBaseException()));
                Debug.LogError("NeRF Dataset Creator: place trained splat —\n" + string.Join("\n", lines));
                return Progress.Status.Failed;
            }
            var result = new List<string>(SplatTrainerChoice.Describe(task.Result));
            if (source == null && SplatSourceTarget.HierarchyPathIn(_datasetFolder) is string path && SceneObjectPath.Find(path) is GameObject found)
            {
                source = found; // the dataset's own target, by its hierarchy path in the loaded scenes
                result.Add("Source object: " + path + " (the dataset's target).");
            }
            result.AddRange(PlaceInScene(task.Result));
            Show(false, result);
            Debug.Log("NeRF Dataset Creator: place trained splat —\n" + string.Join("\n", lines));
            return Progress.Status.Succeeded;
        }

        /// <summary>The lines for a placement that failed: each problem with its field and fix, else the error's message.</summary>
        public static IReadOnlyList<string> Refusal(Exception e)
        {
            if (e is InvalidParameterException invalid) return invalid.Problems.Select(p => p.ToString()).ToList();
            if (e == null) return new[] { "The placement was cut off by Unity before it ended (Play mode, a script reload or quitting). Place again." };
            return new[] { "Nothing was placed: " + e.Message };
        }

        /// <summary>Places (or, without a viewer, describes) the splat object under the source's parent.</summary>
        IReadOnlyList<string> PlaceInScene(SplatPlacement placement)
        {
            var result = new List<string>();
            if (placement.ObjectToWorld == null || placement.ObjectToWorld.Length != 16)
            {
                result.Add("Not placed: the placement has no object_to_world matrix.");
                return result;
            }
            var parent = source != null ? source.transform.parent : null;
            var local = SplatUnderParent.Local(parent != null ? ToCore(parent.worldToLocalMatrix) : (Matrix4x4d?)null,
                Matrix4x4d.FromRowMajor(placement.ObjectToWorld), out var problem);
            if (local == null)
            {
                result.Add("Placed at the scene root instead of under " + parent.name + ": " + problem);
                parent = null;
                local = SplatUnderParent.Local(null, Matrix4x4d.FromRowMajor(placement.ObjectToWorld), out problem);
                if (local == null) { result.Add("Not placed: " + problem); return result; }
            }
            var viewer = SplatViewers.Installed;
            if (viewer == null)
            {
                result.Add(SplatViewers.InstallHint);
                return result;
            }
            var name = (source != null ? source.name : "Trained") + " (splat)";
            var placedResult = viewer.Place(placement.PlyPath, parent, local, name, placed);
            if (placedResult.Placed != null) placed = placedResult.Placed;
            result.AddRange(placedResult.Lines);
            return result;
        }

        /// <summary>Shows the splat and hides the source, or the other way round, as one undoable step (GameObject.SetActive,
        /// UnityCsReference Runtime/Export/Scripting/GameObject.bindings.cs:280 / :287; Undo.RecordObjects).</summary>
        public void ShowSplat(bool splat)
        {
            var objects = new[] { source, placed }.Where(o => o != null).Cast<UnityEngine.Object>().ToArray();
            Undo.IncrementCurrentGroup(); // each toggle its own undo step (Undo.bindings.cs:224 on 2022.3.76f1 and 6000.0.78f1)
            Undo.RecordObjects(objects, splat ? "Show splat" : "Show source");
            if (placed != null) placed.SetActive(splat);
            if (source != null) source.SetActive(!splat);
        }

        /// <summary>Aligns the last active Scene view to train camera <paramref name="index"/> of the dataset.</summary>
        public void ViewFromCamera(string datasetFolder, int index)
        {
            try
            {
                var cameras = TrainCameras(datasetFolder);
                if (index >= cameras.Count)
                {
                    Show(true, new[] { "Camera " + index + " does not exist: the dataset has " + cameras.Count + " train cameras (0 … " + (cameras.Count - 1) + ")." });
                    return;
                }
                var view = SceneView.lastActiveSceneView;
                if (view == null)
                {
                    Show(true, new[] { "No Scene view is open: open one (Window ▸ General ▸ Scene) and press View again." });
                    return;
                }
                var lookAt = source != null ? source.transform.position : (placed != null ? placed.transform.position : (Vector3?)null);
                Show(false, SceneViewCameraAlignment.Describe(index, SceneViewCameraAlignment.Align(view, cameras[index], lookAt)));
            }
            catch (InvalidParameterException e)
            {
                Show(true, Refusal(e));
            }
        }

        IReadOnlyList<ImportedCamera> TrainCameras(string datasetFolder)
        {
            var path = DatasetFolder.SplitPath(datasetFolder, "train");
            if (_cameras == null || _camerasFrom != path)
            {
                _cameras = TransformsPoseReader.ReadFile(path);
                _camerasFrom = path;
            }
            return _cameras.Cameras;
        }

        void Show(bool error, IEnumerable<string> text)
        {
            failed = error;
            lines = text.ToList();
        }

        static Matrix4x4d ToCore(Matrix4x4 m) => Matrix4x4d.FromRowMajor(UnityFrameText.RowMajor((row, column) => m[row, column]));
    }
}
