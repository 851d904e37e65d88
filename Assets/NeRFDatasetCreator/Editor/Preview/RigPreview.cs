using System;
using System.Collections.Generic;
using System.Globalization;
using UnityEditor;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Draws a planned rig in every Scene view while enabled: one small frustum per camera in its split's colour,
    /// the target's bounds, the rig-distance sphere and each inside-out volume's box in its split's colour, with per-split visibility toggles in a Scene-view overlay
    /// (<see cref="RigPreviewOverlay"/>, which users can move and dock like Unity's own).
    /// Clicking near a camera selects it and labels it "train r_12" (its image file). All geometry comes from Core
    /// (<see cref="RigPreviewGeometry"/>, <see cref="MarkerPicking"/>) and is converted to Unity vectors once per
    /// plan change, so drawing a frame allocates nothing.
    /// </summary>
    public sealed class RigPreview : IDisposable
    {
        public static readonly Color TrainColor = ToUnity(SplitColors.Train);
        public static readonly Color ValColor = ToUnity(SplitColors.Val);
        public static readonly Color TestColor = ToUnity(SplitColors.Test);
        public static readonly Color GuideColor = ToUnity(SplitColors.Guides);

        static readonly int ControlHint = "NerfDatasetCreator.RigPreview".GetHashCode();
        static readonly Color[] Colors = { TrainColor, ValColor, TestColor };
        static readonly Vector3[] NoPoints = new Vector3[0];

        readonly bool[] visible = { true, true, true };
        readonly Vector3[][] segments = { NoPoints, NoPoints, NoPoints };
        readonly string[] toggleLabels = { "train", "val", "test" };
        Matrix4x4[] boxMatrices = new Matrix4x4[0];
        int[] boxSplits = new int[0];
        PreviewMarker[] markers = new PreviewMarker[0];
        Vector3[] markerPositions = NoPoints;
        double[] guiX = new double[0];
        double[] guiY = new double[0];
        bool hasPlan;
        bool subscribed;
        Vector3 targetCentre;
        Vector3 targetSize;
        float distance;
        int selected = -1;
        string selectedLabel = "";

        /// <summary>Raised when the user clicks a camera: its split, index and position.</summary>
        public event Action<PreviewMarker> Picked;

        /// <summary>Whether to show the per-split toggle overlay in the Scene view (the window may show its own).</summary>
        public bool ShowOverlay { get; set; } = true;

        /// <summary>The preview the Scene-view overlay shows: the last one enabled, until it is disabled.</summary>
        internal static RigPreview Active { get; private set; }

        /// <summary>Whether the overlay has something to show for this preview.</summary>
        internal bool WantsOverlay => subscribed && hasPlan && ShowOverlay;

        /// <summary>The picked camera, if any.</summary>
        public PreviewMarker? Selected => selected >= 0 && selected < markers.Length ? markers[selected] : (PreviewMarker?)null;

        public static Color ColorOf(PreviewSplit split) => Colors[(int)split];

        public bool IsVisible(PreviewSplit split) => visible[(int)split];

        public void SetVisible(PreviewSplit split, bool show)
        {
            if (visible[(int)split] == show) return;
            visible[(int)split] = show;
            if (!show && selected >= 0 && markers[selected].Split == split) Deselect();
            SceneView.RepaintAll();
        }

        /// <summary>Starts drawing in every Scene view. Call from the window's OnEnable.</summary>
        public void Enable()
        {
            if (subscribed) return;
            SceneView.duringSceneGui += OnSceneGui;
            subscribed = true;
            Active = this;
            SceneView.RepaintAll();
        }

        /// <summary>Stops drawing. Call from the window's OnDisable; Dispose does the same.</summary>
        public void Disable()
        {
            if (!subscribed) return;
            SceneView.duringSceneGui -= OnSceneGui;
            subscribed = false;
            if (Active == this) Active = null;
            SceneView.RepaintAll();
        }

        public void Dispose() => Disable();

        /// <summary>
        /// Shows a new plan: the poses of each split in view order (null for none), the capture camera's vertical
        /// FOV and aspect (width / height), the target's bounds, the rig distance (0 for no sphere) and the volume
        /// splits' boxes (null for none), all in Unity world units.
        /// Invalid camera values clear the preview instead of throwing: the window shows Core's validation for them.
        /// </summary>
        public void SetPlan(IReadOnlyList<UnityPose> train, IReadOnlyList<UnityPose> val, IReadOnlyList<UnityPose> test,
            double verticalFovDegrees, double aspect, Vector3d boundsCentre, Vector3d boundsSize, double rigDistance,
            IReadOnlyList<KeyValuePair<DatasetSplit, OrientedBox>> volumes = null)
        {
            RigPreviewGeometry geometry;
            try
            {
                geometry = RigPreviewGeometry.Build(train, val, test, verticalFovDegrees, aspect, FrustumGeometry.SuggestedLength(rigDistance));
            }
            catch (InvalidParameterException)
            {
                ClearPlan();
                return;
            }

            foreach (var split in RigPreviewGeometry.Splits)
            {
                var points = geometry.Segments(split);
                var converted = points.Count == 0 ? NoPoints : new Vector3[points.Count];
                for (var i = 0; i < points.Count; i++) converted[i] = ToUnity(points[i]);
                segments[(int)split] = converted;
            }

            var count = geometry.Markers.Count;
            if (markers.Length != count)
            {
                markers = new PreviewMarker[count];
                markerPositions = new Vector3[count];
                guiX = new double[count];
                guiY = new double[count];
                Deselect();
            }
            var perSplit = new int[3];
            for (var i = 0; i < count; i++)
            {
                markers[i] = geometry.Markers[i];
                markerPositions[i] = ToUnity(markers[i].Position);
                perSplit[(int)markers[i].Split]++;
            }
            foreach (var split in RigPreviewGeometry.Splits)
                toggleLabels[(int)split] = SplitColors.NameOf(split) + " (" + perSplit[(int)split].ToString(CultureInfo.InvariantCulture) + ")";
            if (selected >= 0) selectedLabel = markers[selected].Label;

            var boxCount = volumes?.Count ?? 0;
            boxMatrices = new Matrix4x4[boxCount];
            boxSplits = new int[boxCount];
            for (var i = 0; i < boxCount; i++)
            {
                boxMatrices[i] = BoxMatrix(volumes[i].Value);
                boxSplits[i] = (int)volumes[i].Key; // DatasetSplit and PreviewSplit share the order train, val, test
            }

            targetCentre = ToUnity(boundsCentre);
            targetSize = ToUnity(boundsSize);
            distance = (float)rigDistance;
            hasPlan = true;
            SceneView.RepaintAll();
        }

        public void ClearPlan()
        {
            hasPlan = false;
            for (var s = 0; s < segments.Length; s++) segments[s] = NoPoints;
            markers = new PreviewMarker[0];
            markerPositions = NoPoints;
            boxMatrices = new Matrix4x4[0];
            boxSplits = new int[0];
            guiX = guiY = new double[0];
            Deselect();
            SceneView.RepaintAll();
        }

        void Deselect()
        {
            selected = -1;
            selectedLabel = "";
        }

        void OnSceneGui(SceneView view)
        {
            if (!hasPlan) return;

            var e = Event.current;
            var id = GUIUtility.GetControlID(ControlHint, FocusType.Passive);
            // The pattern of Unity's own Handles.Button (UnityCsReference 2022.3 Editor/Mono/EditorHandles/Button.cs):
            // report a distance on Layout, take the mouse on MouseDown if nearest, act on MouseUp.
            switch (e.GetTypeForControl(id))
            {
                case EventType.Layout:
                    if (NearestMarker(view.camera, e.mousePosition, out var pixels) >= 0)
                        HandleUtility.AddControl(id, (float)pixels);
                    break;
                case EventType.MouseDown:
                    if (HandleUtility.nearestControl == id && e.button == 0 && !e.alt)
                    {
                        GUIUtility.hotControl = id;
                        e.Use();
                    }
                    break;
                case EventType.MouseUp:
                    if (GUIUtility.hotControl == id && e.button == 0)
                    {
                        GUIUtility.hotControl = 0;
                        e.Use();
                        var picked = NearestMarker(view.camera, e.mousePosition, out _);
                        if (picked >= 0)
                        {
                            selected = picked;
                            selectedLabel = markers[picked].Label;
                            Picked?.Invoke(markers[picked]);
                            view.Repaint();
                        }
                    }
                    break;
                case EventType.Repaint:
                    Draw();
                    break;
            }
        }

        void Draw()
        {
            using (new Handles.DrawingScope(GuideColor))
            {
                Handles.DrawWireCube(targetCentre, targetSize);
                if (distance > 0)
                {
                    Handles.DrawWireDisc(targetCentre, Vector3.up, distance);
                    Handles.DrawWireDisc(targetCentre, Vector3.right, distance);
                    Handles.DrawWireDisc(targetCentre, Vector3.forward, distance);
                }
            }
            // A volume's box: the unit cube through the box's TRS matrix. Handles.DrawingScope(Color, Matrix4x4) sets
            // Handles.matrix, and DrawWireCube multiplies its vertices by it (GL.MultMatrix(matrix); UnityCsReference
            // 2022.3 Editor/Mono/Handles.cs:115, 476–482; 6000.0 Editor/Mono/Handles/Handles.cs:115, 476), so a turned,
            // non-uniformly scaled box is drawn exactly as Core samples it (OrientedBox.PointAt).
            for (var i = 0; i < boxMatrices.Length; i++)
            {
                if (!visible[boxSplits[i]]) continue;
                using (new Handles.DrawingScope(Colors[boxSplits[i]], boxMatrices[i]))
                    Handles.DrawWireCube(Vector3.zero, Vector3.one);
            }
            for (var s = 0; s < segments.Length; s++)
            {
                if (!visible[s] || segments[s].Length == 0) continue;
                using (new Handles.DrawingScope(Colors[s]))
                    Handles.DrawLines(segments[s]);
            }
            if (selected < 0) return;
            var position = markerPositions[selected];
            using (new Handles.DrawingScope(Colors[(int)markers[selected].Split]))
            {
                Handles.DotHandleCap(0, position, Quaternion.identity, 0.06f * HandleUtility.GetHandleSize(position), EventType.Repaint);
                Handles.Label(position, selectedLabel);
            }
        }

        /// <summary>The overlay's contents: a toggle per split in its colour and the picked camera.</summary>
        internal void DrawOverlayContents()
        {
            var original = GUI.contentColor;
            for (var s = 0; s < visible.Length; s++)
            {
                GUI.contentColor = Colors[s];
                var show = GUILayout.Toggle(visible[s], toggleLabels[s]);
                if (show != visible[s]) SetVisible((PreviewSplit)s, show);
            }
            GUI.contentColor = original;
            GUILayout.Label(selected >= 0 ? selectedLabel : "click a camera for its index");
        }

        /// <summary>The visible marker nearest to the mouse within Unity's pick distance, or −1. Reuses its buffers.</summary>
        int NearestMarker(Camera camera, Vector2 mouse, out double pixels)
        {
            pixels = double.PositiveInfinity;
            if (camera == null) return -1;
            for (var i = 0; i < markers.Length; i++)
            {
                if (!visible[(int)markers[i].Split])
                {
                    guiX[i] = guiY[i] = double.NaN;
                    continue;
                }
                var p = HandleUtility.WorldToGUIPointWithDepth(camera, markerPositions[i]);
                // z is the depth in front of the camera; a point behind it projects mirrored and must not be picked.
                guiX[i] = p.z > 0 ? p.x : double.NaN;
                guiY[i] = p.z > 0 ? p.y : double.NaN;
            }
            return MarkerPicking.Nearest(guiX, guiY, markers.Length, mouse.x, mouse.y, MarkerPicking.DefaultRadiusPixels, out pixels);
        }

        /// <summary>
        /// The matrix that takes the unit cube centred at the origin onto <paramref name="box"/>: translation, rotation,
        /// then the size as scale (Matrix4x4.TRS), so that corner (±½, ±½, ±½) lands on Core's
        /// <see cref="OrientedBox.PointAt"/> of it.
        /// </summary>
        public static Matrix4x4 BoxMatrix(OrientedBox box)
        {
            var r = box.Rotation;
            return Matrix4x4.TRS(ToUnity(box.Centre), new Quaternion((float)r.X, (float)r.Y, (float)r.Z, (float)r.W), ToUnity(box.Size));
        }

        static Vector3 ToUnity(Vector3d v) => new Vector3((float)v.X, (float)v.Y, (float)v.Z);

        static Color ToUnity(RgbaColor c) => new Color(c.R, c.G, c.B, c.A);
    }
}
