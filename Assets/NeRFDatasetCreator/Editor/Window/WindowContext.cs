using System;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// What the sections draw and edit during one OnGUI event: a working copy of the settings (the window commits it
    /// as one undo step when a control changed it), the current problems, and the scene objects the settings name.
    /// </summary>
    sealed class WindowContext
    {
        public WindowContext(DatasetSettings settings, FieldProblems problems, GameObject target, TargetInfo targetInfo,
            Camera templateCamera, bool busy, WindowFoldouts foldouts, Action<Action> later)
        {
            Settings = settings;
            Problems = problems ?? FieldProblems.None;
            Target = target;
            TargetInfo = targetInfo;
            TemplateCamera = templateCamera;
            Busy = busy;
            Foldouts = foldouts;
            Later = later;
        }

        /// <summary>The working copy that the controls edit.</summary>
        public DatasetSettings Settings { get; }

        public FieldProblems Problems { get; }

        /// <summary>The target object; a section that changes it also changes <see cref="DatasetSettings.Target"/>.</summary>
        public GameObject Target { get; set; }

        /// <summary>The target's measured size, or null without a target.</summary>
        public TargetInfo TargetInfo { get; }

        public Camera TemplateCamera { get; set; }

        /// <summary>A one-off note about the last pick (e.g. a refused prefab asset), kept by the window until the next pick.</summary>
        public string PickNotice { get; set; }

        /// <summary>A capture is running: settings are read-only until it ends.</summary>
        public bool Busy { get; }

        public WindowFoldouts Foldouts { get; }

        /// <summary>
        /// Runs an action after this GUI event (EditorApplication.delayCall): dialogs, framing and capture never run
        /// inside OnGUI, where a modal dialog or a render would break the window's layout state.
        /// </summary>
        public Action<Action> Later { get; }

        /// <summary>
        /// Opens the imported-cameras picker for a split (start folder, folder rather than file) and stores the pick
        /// in the window's settings; set by the window, called from <see cref="Later"/>.
        /// </summary>
        public Action<DatasetSplit, string, bool> PickCameras { get; set; }
    }
}
