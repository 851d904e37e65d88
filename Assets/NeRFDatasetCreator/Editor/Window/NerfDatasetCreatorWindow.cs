using System;
using System.Collections.Generic;
using System.IO;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Window ▸ NeRF Dataset Creator: the steps of making a dataset in the order of the work, with Core's validation
    /// under each field as you type, the rig drawn in the Scene view, presets, batch configs and a background or
    /// foreground capture (one at a time, editor-wide: a reopened window shows the running one).
    /// Settings live in <see cref="NerfDatasetCreatorSettings"/> (per project, undoable); this window keeps only the
    /// scene objects they name and what is open.
    /// </summary>
    public sealed partial class NerfDatasetCreatorWindow : EditorWindow
    {
        const string EditUndoName = "Edit NeRF dataset settings";

        [SerializeField] GameObject target;
        [SerializeField] Camera templateCamera;
        [SerializeField] NerfDatasetPreset preset;
        [SerializeField] WindowFoldouts foldouts = new WindowFoldouts();
        [SerializeField] ConfigReport report = new ConfigReport();
        [SerializeField] Vector2 scroll;
        [SerializeField] bool previewOn = true;
        [SerializeField] bool foregroundCapture;

        readonly CaptureController capture = new CaptureController();
        PreviewDriver preview;
        FieldProblems problems = FieldProblems.None;
        TargetInfo targetInfo;
        string pickNotice;
        string seenKey;
        // Re-checks run half a second after the last change, never at the 10 Hz tick, and ignore the scene events of
        // their own copies (review S3-2; Core RecheckSchedule).
        readonly RecheckSchedule recheck = new RecheckSchedule();
        double lastTick;

        static double Now => EditorApplication.timeSinceStartup;

        /// <summary>How often the window follows the target and re-checks: Unity's own inspector rate (10 per second).</summary>
        const double TickSeconds = 0.1;

        [MenuItem("Window/NeRF Dataset Creator")]
        public static void Open()
        {
            var window = GetWindow<NerfDatasetCreatorWindow>("NeRF Dataset Creator");
            window.minSize = new Vector2(340, 400);
        }

        static NerfDatasetCreatorSettings Store => NerfDatasetCreatorSettings.instance;

        /// <summary>The project folder (the parent of Assets/): relative output folders and the default folder are resolved against it.</summary>
        static string ProjectRoot => Path.GetDirectoryName(Application.dataPath);

        void OnEnable()
        {
            preview = new PreviewDriver();
            preview.Changed += Repaint;
            preview.Enabled = previewOn;
            Undo.undoRedoPerformed += OnUndoRedo;
            CaptureController.Changed += Repaint;
            DatasetToolRunner.Changed += Repaint;
            // Editor-wide events rather than the OnHierarchyChange / OnInspectorUpdate messages, which Unity sends only
            // to the visible tab of a dock area (HostView), so the preview keeps following a docked-away window too.
            EditorApplication.hierarchyChanged += OnHierarchyChanged;
            EditorApplication.update += OnEditorUpdate;
            FollowSceneObjects();
            recheck.Changed(Now);
        }

        void OnDisable()
        {
            Undo.undoRedoPerformed -= OnUndoRedo;
            CaptureController.Changed -= Repaint;
            DatasetToolRunner.Changed -= Repaint;
            EditorApplication.hierarchyChanged -= OnHierarchyChanged;
            EditorApplication.update -= OnEditorUpdate;
            preview?.Dispose();
            preview = null;
        }

        // The disk may have changed while the window was in the background (a dataset deleted or created).
        void OnFocus() => recheck.Changed(Now);

        void OnHierarchyChanged()
        {
            // A check's own preview-scene copies may raise this (synchronously or on the next update): not an edit.
            if (DatasetCapture.IsPreparing) return;
            FollowSceneObjects();
            recheck.SceneChanged(Now);
        }

        void OnUndoRedo()
        {
            // Raised for every undo and redo in the editor; only one that changed the plugin's settings is saved.
            Store.SaveIfChanged();
            ResolveSceneObjects();
            recheck.Changed(Now);
            Repaint();
        }

        /// <summary>
        /// Ten times a second: follows the target's transform and size, rebuilds the preview when the plan changed, and
        /// re-validates half a second after anything validation reads stopped changing.
        /// </summary>
        void OnEditorUpdate()
        {
            var now = EditorApplication.timeSinceStartup;
            if (now - lastTick < TickSeconds || preview == null) return;
            lastTick = now;
            var settings = Store.Settings;
            targetInfo = TargetInfo.Of(target);
            if (preview.Enabled) preview.Update(settings, targetInfo);
            if (capture.IsRunning)
            {
                // The run's own folder is being written: checking it now would only report the run itself.
                Repaint();
                return;
            }
            var key = CheckKey(settings);
            if (key != seenKey)
            {
                seenKey = key;
                recheck.Changed(now);
            }
            if (recheck.Due(now)) Check(settings);
        }

        string CheckKey(DatasetSettings settings)
        {
            var measure = targetInfo?.Measure ?? PlanTarget.AtOrigin;
            return DatasetSettingsJson.Write(settings) + "|" + (target == null ? 0 : target.GetInstanceID()) + "|" +
                   measure.Centre + "|" + measure.BoundingRadius.ToString("R", System.Globalization.CultureInfo.InvariantCulture);
        }

        /// <summary>Runs the capture's own checks (settings, output folder, target, environment) so the window shows exactly what Create would refuse.</summary>
        void Check(DatasetSettings settings)
        {
            recheck.Starting();
            var warnings = new List<ValidationProblem>();
            List<ValidationProblem> errors;
            try
            {
                var prepared = DatasetCapture.Prepare(settings.Clone(), target, ProjectRoot);
                errors = new List<ValidationProblem>(prepared.Problems);
                warnings.AddRange(prepared.Warnings);
            }
            catch (Exception e)
            {
                errors = new List<ValidationProblem> { new ValidationProblem("capture", e.GetType().Name, e.Message, "Report this with the console log.") };
            }
            finally
            {
                recheck.Finished(Now);
            }
            var targetPath = SceneObjectPath.Check(WindowFields.Target, target);
            if (targetPath != null) warnings.Add(targetPath);
            problems = new FieldProblems(errors, warnings);
            Repaint();
        }

        void OnGUI()
        {
            var context = new WindowContext(Store.Settings.Clone(), problems, target, targetInfo, templateCamera, capture.IsRunning, foldouts,
                action => EditorApplication.delayCall += () => action())
            {
                PickNotice = pickNotice,
                PickCameras = ChooseCameras,
            };
            scroll = EditorGUILayout.BeginScrollView(scroll);
            preset = PresetSection.Draw(context, preset, report, new PresetSection.Actions
            {
                SavePreset = SavePreset,
                LoadPreset = LoadPreset,
                SaveConfig = SaveConfig,
                LoadConfig = LoadConfig,
            });

            using (new EditorGUI.DisabledScope(capture.IsRunning))
            {
                EditorGUI.BeginChangeCheck();
                TargetSection.Draw(context);
                CameraSection.Draw(context);
                RigSection.Draw(context);
                TimeSection.Draw(context);
                OutputsSection.Draw(context);
                OutputFolderSection.Draw(context, ProjectRoot, ChooseFolder);
                if (EditorGUI.EndChangeCheck()) Commit(context.Settings, EditUndoName);
            }
            target = context.Target;
            templateCamera = context.TemplateCamera;
            pickNotice = context.PickNotice;

            PreviewSection.Draw(preview);
            previewOn = preview.Enabled;
            foregroundCapture = CreateSection.Draw(context, capture, StartCapture, foregroundCapture);
            if (!capture.IsRunning) ExportSection.Draw(capture.LastResult);
            EditorGUILayout.EndScrollView();
        }

        /// <summary>Stores edited settings as one undo step, unless nothing actually changed (a click on the same value).</summary>
        void Commit(DatasetSettings edited, string undoName)
        {
            if (DatasetSettingsJson.Write(edited) == DatasetSettingsJson.Write(Store.Settings)) return;
            Store.Apply(edited, undoName);
            recheck.Changed(Now);
            Repaint();
        }

        /// <summary>
        /// After a hierarchy change or a domain reload: an object the window still holds keeps being the target even
        /// when it was renamed or moved (its stored path follows it); an object that is gone is looked up by path.
        /// </summary>
        void FollowSceneObjects()
        {
            var settings = Store.Settings;
            var changed = false;
            if (target != null && SceneObjectPath.Of(target) != settings.Target)
            {
                settings.Target = SceneObjectPath.Of(target);
                settings.Scene = target.scene.path;
                changed = true;
            }
            if (templateCamera != null && settings.Camera != null && SceneObjectPath.Of(templateCamera.gameObject) != settings.Camera.CopyFromCamera)
            {
                settings.Camera.CopyFromCamera = SceneObjectPath.Of(templateCamera.gameObject);
                changed = true;
            }
            // A path that follows a rename is not an edit of the user's: it is saved, but not as an undo step.
            if (changed) Store.SaveToProject();
            ResolveSceneObjects();
        }

        /// <summary>Finds the target and template camera from their stored paths (after a restart, an undo, or a config load).</summary>
        void ResolveSceneObjects()
        {
            var settings = Store.Settings;
            if (SceneObjectPath.Of(target) != settings.Target) target = SceneObjectPath.Find(settings.Target);
            var cameraPath = settings.Camera?.CopyFromCamera ?? "";
            var currentCamera = templateCamera == null ? "" : SceneObjectPath.Of(templateCamera.gameObject);
            if (currentCamera != cameraPath)
            {
                var found = SceneObjectPath.Find(cameraPath);
                templateCamera = found == null ? null : found.GetComponent<Camera>();
            }
        }

        void StartCapture()
        {
            if (this == null) return;
            capture.Start(Store.Settings, target, ProjectRoot, foregroundCapture);
        }

        /// <summary>Whether a capture is running in this editor (this window shows any, whoever started it).</summary>
        public bool IsCapturing => capture.IsRunning;

        /// <summary>How the last capture started from a window ended (kept across domain reloads), or null.</summary>
        public DatasetCaptureResult LastCaptureResult => capture.LastResult;
    }
}
