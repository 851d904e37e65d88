using System;
using System.Collections.Generic;
using System.Linq;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Feeds the Scene-view <see cref="RigPreview"/> with the plan of the window's settings while the window is open.
    /// The plan is rebuilt only when the camera-shaping settings or the target's centre or size change
    /// (<see cref="PreviewPlanKey"/>), not on every repaint.
    /// </summary>
    sealed class PreviewDriver : IDisposable
    {
        readonly RigPreview _preview = new RigPreview();
        const string StaleNote = "The animated camera's poses are from the window's last check; they follow half a second after the scene stops changing.";

        PreviewPlanKey _key;
        Bounds _bounds;
        bool _enabled;

        public PreviewDriver()
        {
            _preview.Picked += marker =>
            {
                PickedLabel = marker.Label;
                Changed?.Invoke();
            };
        }

        /// <summary>Raised when the user picks a camera in the Scene view.</summary>
        public event Action Changed;

        public RigPreview Preview => _preview;

        /// <summary>"train r_12" after a click on a camera; empty before.</summary>
        public string PickedLabel { get; private set; } = "";

        /// <summary>Why nothing is drawn, or empty when the rig is drawn.</summary>
        public string Status { get; private set; } = "";

        /// <summary>Views per split of the drawn plan.</summary>
        public int[] Counts { get; } = new int[3];

        public bool Enabled
        {
            get => _enabled;
            set
            {
                if (value == _enabled) return;
                _enabled = value;
                if (value) _preview.Enable();
                else _preview.Disable();
            }
        }

        /// <summary>Rebuilds the drawn plan when the settings or the target changed since the last call.</summary>
        public void Update(DatasetSettings settings, TargetInfo target)
        {
            if (target == null || !target.HasRenderers)
            {
                Clear(target == null ? "Pick a target to see the rig." : "The target has no renderers to aim at.");
                return;
            }
            settings = settings.Clone();
            // Moving a scene camera changes the key (PreviewPlanKey). Animated cameras are never sampled here (ten times a
            // second): the rig shows the window's last check's samples, marked stale until the next check (review S3-2).
            var stale = SceneCameraSources.Resolve(settings, sampleAnimations: false);
            var key = PreviewPlanKey.Of(settings, target.Measure);
            // The plan ignores the target's rotation, but its renderers' box turns with it: compare that too.
            if (key.Equals(_key) && target.Bounds == _bounds)
            {
                if (Status.Length == 0 || Status == StaleNote) Status = stale ? StaleNote : "";
                return;
            }
            _key = key;
            _bounds = target.Bounds;

            var problems = CapturePlan.Check(settings, target.Measure);
            if (problems.Count > 0)
            {
                _preview.ClearPlan();
                Array.Clear(Counts, 0, Counts.Length);
                Status = "The rig is hidden until the problems marked in red are fixed.";
                return;
            }
            var plan = CapturePlan.Build(settings, target.Measure);
            var poses = DatasetSplits.All.Select(split => (IReadOnlyList<UnityPose>)plan.ViewsOf(split).Select(v => v.Pose).ToList()).ToList();
            for (var i = 0; i < 3; i++) Counts[i] = poses[i].Count;
            var bounds = target.Bounds;
            _preview.SetPlan(poses[0], poses[1], poses[2], plan.Settings.Camera.VerticalFovDegrees, (double)plan.Settings.Width / plan.Settings.Height,
                new Vector3d(bounds.center.x, bounds.center.y, bounds.center.z), new Vector3d(bounds.size.x, bounds.size.y, bounds.size.z),
                CameraSourcePlanning.AnyFormation(plan.Settings) ? plan.Distance : 0, VolumePlanning.Boxes(plan));
            Status = stale ? StaleNote : "";
        }

        void Clear(string status)
        {
            if (_key != null || Status != status)
            {
                _preview.ClearPlan();
                Array.Clear(Counts, 0, Counts.Length);
            }
            _key = null;
            Status = status;
        }

        public void Dispose() => _preview.Dispose();
    }
}
