using System;
using System.IO;
using System.Linq;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Window ▸ NeRF Dataset Tools: the headless tool's demo, validate, check, convert, evaluate, merge and clean on any folder (datasets live
    /// outside Assets/, where the Project window's context menu does not reach), run in the editor by
    /// <see cref="DatasetToolRunner"/> with the tool's own messages and the equivalent terminal command.
    /// </summary>
    public sealed class DatasetToolsWindow : EditorWindow
    {
        [SerializeField] string datasetFolder = "";
        [SerializeField] string exportFolder = "";
        [SerializeField] string rendersFolder = "";
        [SerializeField] string objectName = "";
        [SerializeField] string shardsFolder = "";
        [SerializeField] string mergedFolder = "";
        [SerializeField] bool moveFiles;
        [SerializeField] string cleanFolder = "";
        [SerializeField] string demoFolder = "";
        [SerializeField] DemoPreset demoPreset = DemoPreset.Static;
        [SerializeField] Vector2 scroll;
        [SerializeField] Vector2 outputScroll;
        [SerializeField] PlaceSplatSection placeSplat = new PlaceSplatSection();

        /// <summary>Place trained splat (issue 34).</summary>
        internal PlaceSplatSection PlaceSplat => placeSplat;

        /// <summary>The exports a button offers, in the order of Documentation~/exports.md.</summary>
        public static readonly (string Label, ExportTarget Target, bool Depths, string Tooltip)[] Exports =
        {
            ("nerfstudio", ExportTarget.Nerfstudio, false, "transforms.json for ns-train nerfstudio-data (with depth and masks when every frame has them)."),
            ("COLMAP / 3DGS", ExportTarget.Colmap, false, "A COLMAP text model with the images: 3D Gaussian Splatting's train.py -s."),
            ("COLMAP + depths", ExportTarget.Colmap, true, "COLMAP plus 3DGS's inverse-depth maps and depth_params.json (train.py -d); needs depth PNGs."),
            ("instant-ngp", ExportTarget.Ngp, false, "transforms.json with instant-ngp's aabb_scale, scale and offset."),
            ("Dynamic 3D Gaussians", ExportTarget.Dynamic3dgs, false, "A multi-view dynamic capture in Dynamic 3D Gaussians' layout (train_meta.json, ims/, seg/, init_pt_cld.npz)."),
            ("Gaussian Grouping", ExportTarget.GaussianGrouping, false, "A dataset captured with labels: the COLMAP model plus object_mask/ per image, object_ids.json and the num_classes config (Documentation~/exports.md, Labels)."),
            ("Replica (SLAM)", ExportTarget.Replica, false, "A monocular dynamic capture with depth as a Replica RGB-D sequence for SplaTAM, MonoGS and Gaussian-SLAM (results/, traj.txt, their configs)."),
            ("TUM RGB-D (SLAM)", ExportTarget.Tum, false, "A monocular dynamic capture with depth as a TUM RGB-D sequence for SplaTAM, MonoGS and Gaussian-SLAM (rgb.txt, depth.txt, groundtruth.txt, their configs)."),
        };

        /// <summary>
        /// Every other <c>convert --to</c> target, in the enum's order, offered in one menu beside the buttons: a target
        /// added to <see cref="ExportTarget"/> is in the window without a line here.
        /// </summary>
        public static readonly ExportTarget[] MoreExports =
            ((ExportTarget[])Enum.GetValues(typeof(ExportTarget))).Where(t => Exports.All(e => e.Target != t)).ToArray();

        /// <summary>The menu's choice for this Editor session (UI state only: a domain reload resets it to the first).</summary>
        static int moreExport;

        [MenuItem("Window/NeRF Dataset Tools")]
        public static void Open() => Open(null);

        /// <summary>Opens the window on <paramref name="folder"/> (e.g. the dataset a capture just wrote).</summary>
        public static DatasetToolsWindow Open(string folder)
        {
            var window = GetWindow<DatasetToolsWindow>("NeRF Dataset Tools");
            window.minSize = new Vector2(360, 380);
            if (!string.IsNullOrEmpty(folder))
            {
                window.datasetFolder = folder;
                window.cleanFolder = Path.GetDirectoryName(folder);
            }
            else if (string.IsNullOrEmpty(window.cleanFolder))
                window.cleanFolder = Path.Combine(ProjectRoot, SafeOutput.DefaultParentFolder);
            if (string.IsNullOrEmpty(window.demoFolder)) window.demoFolder = DefaultDemoFolder;
            return window;
        }

        static string ProjectRoot => Path.GetDirectoryName(Application.dataPath);

        /// <summary>Where the Demo button writes unless told otherwise: beside the captures, outside Assets (no import).</summary>
        internal static string DefaultDemoFolder => Path.Combine(ProjectRoot, SafeOutput.DefaultParentFolder, "demo");

        void OnEnable() => DatasetToolRunner.Changed += Repaint;

        void OnDisable() => DatasetToolRunner.Changed -= Repaint;

        void OnGUI()
        {
            scroll = EditorGUILayout.BeginScrollView(scroll);
            using (new EditorGUI.DisabledScope(DatasetToolRunner.IsRunning))
            {
                DrawDemo();
                EditorGUILayout.Space();
                EditorGUILayout.LabelField("Check and export a dataset", EditorStyles.boldLabel);
                datasetFolder = FolderField("Dataset folder", datasetFolder, "A Blender-format dataset: a capture, a merged shard set, or nerf_synthetic.", f => datasetFolder = f);
                using (new EditorGUI.DisabledScope(string.IsNullOrWhiteSpace(datasetFolder)))
                {
                    EditorGUILayout.BeginHorizontal();
                    if (GUILayout.Button(new GUIContent("Validate", "nerf-dataset validate: every problem a loader would trip on.")))
                        Run("validate", ValidateCommand.Arguments(datasetFolder));
                    if (GUILayout.Button(new GUIContent("Check", "nerf-dataset check: decodes the images and checks that alpha, masks, depth, normals, poses and point cloud agree (Documentation~/check.md).")))
                        Run("check", CheckCommand.Arguments(datasetFolder));
                    EditorGUILayout.EndHorizontal();
                    exportFolder = FolderField("Export into", exportFolder, "Empty: the format's default folder inside the dataset (nerfstudio/, colmap/, ngp/, dynamic3dgs/). Nothing is ever overwritten.", f => exportFolder = f);
                    DrawExportButtons(datasetFolder, exportFolder);
                    // convert --to nerfstudio --object: masks of one labelled object (Documentation~/exports.md, Labels).
                    EditorGUILayout.BeginHorizontal();
                    objectName = EditorGUILayout.TextField(new GUIContent("One object", "A labelled object's name, hierarchy path or instance id (labels.json)."), objectName);
                    using (new EditorGUI.DisabledScope(string.IsNullOrWhiteSpace(objectName)))
                        if (GUILayout.Button(new GUIContent("nerfstudio masks", "transforms.json whose mask_path keeps only this object, so nerfstudio trains it alone."), GUILayout.Width(130)))
                            Run("export of " + objectName, ConvertCommand.Arguments(datasetFolder, ExportTarget.Nerfstudio, exportFolder, objectName: objectName));
                    EditorGUILayout.EndHorizontal();
                    rendersFolder = FolderField("Trained renders", rendersFolder, "A trainer's renders of the test split: a 3DGS model folder, ns-render dataset output, instant-ngp screenshots or r_<i>.png files (Documentation~/evaluate.md).", f => rendersFolder = f);
                    using (new EditorGUI.DisabledScope(string.IsNullOrWhiteSpace(rendersFolder)))
                        if (GUILayout.Button(new GUIContent("Evaluate renders", "nerf-dataset evaluate: PSNR, SSIM, masked PSNR, depth and normal errors; writes metrics.json, error maps and report.html beside the renders.")))
                            Run("evaluate", EvaluateCommand.Arguments(datasetFolder, rendersFolder));
                }

                EditorGUILayout.Space();
                placeSplat.Draw(this, datasetFolder, FolderField);

                EditorGUILayout.Space();
                EditorGUILayout.LabelField("Merge the shards of a batch capture", EditorStyles.boldLabel);
                shardsFolder = FolderField("Shards folder", shardsFolder, "The folder holding the shard folders (each with its shard.json).", f => shardsFolder = f);
                var shards = MergeCommand.ShardFoldersIn(shardsFolder);
                if (!string.IsNullOrWhiteSpace(shardsFolder))
                    EditorGUILayout.LabelField(" ", shards.Count == 0 ? "No shard folder (with shard.json) inside." : shards.Count + " shard folders: " + string.Join(", ", shards.Select(Path.GetFileName)), EditorStyles.wordWrappedMiniLabel);
                mergedFolder = FolderField("Merged dataset", mergedFolder, "A folder that does not exist yet.", f => mergedFolder = f);
                moveFiles = EditorGUILayout.Toggle(new GUIContent("Move the images", "Move instead of copy: no extra disk space, and the shards are emptied."), moveFiles);
                using (new EditorGUI.DisabledScope(shards.Count == 0 || string.IsNullOrWhiteSpace(mergedFolder)))
                    if (GUILayout.Button("Merge"))
                        Run("merge", MergeCommand.Arguments(mergedFolder, shards, moveFiles));

                EditorGUILayout.Space();
                EditorGUILayout.LabelField("Leftovers of interrupted runs", EditorStyles.boldLabel);
                cleanFolder = FolderField("Folder", cleanFolder, "The folder holding the datasets (e.g. NeRFDatasets) or a dataset.", f => cleanFolder = f);
                using (new EditorGUI.DisabledScope(string.IsNullOrWhiteSpace(cleanFolder)))
                {
                    EditorGUILayout.BeginHorizontal();
                    if (GUILayout.Button("List them (dry run)")) Run("clean --dry-run", CleanCommand.Arguments(cleanFolder, dryRun: true));
                    if (GUILayout.Button("Clean")) Run("clean", CleanCommand.Arguments(cleanFolder));
                    EditorGUILayout.EndHorizontal();
                }
            }
            EditorGUILayout.Space();
            DrawLastRun(ref outputScroll);
            EditorGUILayout.EndScrollView();
        }

        /// <summary>
        /// nerf-dataset demo: a checked dataset of the built-in analytic scene, no capture needed, so that Check, the exports
        /// and Evaluate can be tried at once; the dataset folder field below is set to it. The preset popup is
        /// EditorGUILayout.EnumPopup(GUIContent, Enum, params GUILayoutOption[]) (UnityCsReference Editor/Mono/EditorGUILayout.cs
        /// line 962 in 2022.3.76f1, 973 in 6000.0.78f1), which lists DemoPreset's names.
        /// </summary>
        void DrawDemo()
        {
            EditorGUILayout.LabelField("Try it: a demo dataset", EditorStyles.boldLabel);
            demoFolder = FolderField("Demo folder", demoFolder, "A new or empty folder, or an earlier demo (replaced). Never inside Assets.", f => demoFolder = f);
            EditorGUILayout.BeginHorizontal();
            demoPreset = (DemoPreset)EditorGUILayout.EnumPopup(new GUIContent("Preset", "static: RGBA, depth, normals, masks; or one feature on top: dynamic, labels, lens, exposure, blur."), demoPreset);
            using (new EditorGUI.DisabledScope(string.IsNullOrWhiteSpace(demoFolder)))
                if (GUILayout.Button(new GUIContent("Write demo", "nerf-dataset demo: a small trainable dataset of a built-in scene, written through the capture's own writers and checked (check_report.json)."), GUILayout.Width(110)))
                {
                    datasetFolder = demoFolder;
                    GUI.FocusControl(null); // a focused text field would keep showing its old text
                    Run("demo", DemoCommand.Arguments(demoFolder, demoPreset));
                }
            EditorGUILayout.EndHorizontal();
        }

        /// <summary>The "Export for …" buttons, shared with the creator window's result (<see cref="ExportSection"/>).</summary>
        internal static void DrawExportButtons(string folder, string outputFolder)
        {
            EditorGUILayout.BeginHorizontal();
            for (var i = 0; i < Exports.Length; i++)
            {
                if (i == 3)
                {
                    EditorGUILayout.EndHorizontal();
                    EditorGUILayout.BeginHorizontal();
                }
                var export = Exports[i];
                if (GUILayout.Button(new GUIContent(export.Label, export.Tooltip)))
                    Run("export for " + export.Label, ConvertCommand.Arguments(folder, export.Target, outputFolder, export.Depths));
            }
            EditorGUILayout.EndHorizontal();
            if (MoreExports.Length == 0) return;
            EditorGUILayout.BeginHorizontal();
            var names = MoreExports.Select(t => ExportTargets.Name(t)).ToArray();
            moreExport = EditorGUILayout.Popup(new GUIContent("More formats", "Every other convert --to target (Documentation~/exports.md says what each writes and what it needs)."),
                Math.Min(moreExport, names.Length - 1), names);
            var chosen = MoreExports[moreExport];
            if (GUILayout.Button(new GUIContent("Export", "nerf-dataset convert --to " + names[moreExport]), GUILayout.Width(70)))
                Run("export for " + names[moreExport], ConvertCommand.Arguments(folder, chosen, outputFolder, false));
            EditorGUILayout.EndHorizontal();
        }

        /// <summary>The running command, or the last one's terminal line, exit and every line it printed.</summary>
        internal static void DrawLastRun(ref Vector2 outputScroll)
        {
            if (DatasetToolRunner.IsRunning)
            {
                EditorGUILayout.HelpBox("Running " + DatasetToolRunner.RunningTitle + "… (progress in Window ▸ General ▸ Background Tasks)", MessageType.None);
                return;
            }
            var last = DatasetToolRunner.Last;
            if (last == null) return;
            EditorGUILayout.LabelField(last.Succeeded ? "Last run: done" : "Last run: exit " + last.ExitCode + (last.ExitCode == ToolExitCodes.UsageError ? " (usage)" : " (refused or problems found)"), EditorStyles.boldLabel);
            EditorGUILayout.SelectableLabel(last.CommandLine, EditorStyles.wordWrappedMiniLabel, GUILayout.Height(EditorGUIUtility.singleLineHeight * 2));
            var text = string.Join("\n", last.Lines);
            // Wrapped height at the view's width, so long lines (the tool's messages are one sentence each) are not cut.
            var height = EditorStyles.wordWrappedLabel.CalcHeight(new GUIContent(text), Mathf.Max(100, EditorGUIUtility.currentViewWidth - 40));
            outputScroll = EditorGUILayout.BeginScrollView(outputScroll, GUILayout.MinHeight(80), GUILayout.MaxHeight(240));
            EditorGUILayout.SelectableLabel(text, EditorStyles.wordWrappedLabel, GUILayout.Height(height));
            EditorGUILayout.EndScrollView();
        }

        static void Run(string title, string[] arguments)
        {
            // After this GUI event: the run changes what the window draws.
            EditorApplication.delayCall += () => DatasetToolRunner.Start(title, arguments);
        }

        /// <summary>
        /// A folder path with a "…" picker. The dialog runs from EditorApplication.delayCall, never inside OnGUI
        /// (a modal dialog there breaks the layout), and stores its pick through <paramref name="store"/>.
        /// </summary>
        string FolderField(string label, string value, string tooltip, System.Action<string> store)
        {
            EditorGUILayout.BeginHorizontal();
            value = EditorGUILayout.TextField(new GUIContent(label, tooltip), value ?? "");
            if (GUILayout.Button("…", GUILayout.Width(28)))
            {
                var start = Directory.Exists(value) ? value : ProjectRoot;
                EditorApplication.delayCall += () =>
                {
                    var chosen = EditorUtility.OpenFolderPanel(label, start, "");
                    if (string.IsNullOrEmpty(chosen) || this == null) return;
                    store(chosen);
                    GUI.FocusControl(null); // a focused text field would keep showing its old text
                    Repaint();
                };
            }
            EditorGUILayout.EndHorizontal();
            return value;
        }
    }
}
