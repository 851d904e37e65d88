using UnityEditor;
using UnityEditor.Overlays;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The rig preview's legend and per-split toggles as a Scene-view overlay, so it docks and moves like Unity's own
    /// instead of covering the Tools overlay at a fixed place. <c>[Overlay(typeof(SceneView), id, displayName,
    /// defaultDisplay)]</c> and <see cref="IMGUIOverlay"/> exist in 2022.3 and 6000.0 (UnityCsReference
    /// Editor/Mono/Overlays/OverlayAttribute.cs:99 / :180, IMGUIOverlay.cs:29,59). As an <see cref="ITransientOverlay"/>
    /// it is shown only while <see cref="visible"/> is true — while the window draws a plan — and then in the active Scene
    /// view (IMGUIOverlay.cs:15-19).
    /// </summary>
    [Overlay(typeof(SceneView), Id, "NeRF rig preview", true)]
    sealed class RigPreviewOverlay : IMGUIOverlay, ITransientOverlay
    {
        public const string Id = "nerf-dataset-creator-rig-preview";

        public bool visible => RigPreview.Active != null && RigPreview.Active.WantsOverlay;

        public override void OnGUI() => RigPreview.Active?.DrawOverlayContents();
    }
}
