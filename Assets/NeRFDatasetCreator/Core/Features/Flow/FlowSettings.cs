using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The "flow" section of the settings (issue 37): exact optical flow, scene flow, occlusion and long tracks of the
    /// target, computed from the geometry pack's per-step meshes (<c>"geometryPack": "everyStep"</c>) and the poses, in
    /// <c>flow/</c> (Documentation~/flow.md). Dynamic captures only. Off by default, and then nothing about the dataset changes.
    /// </summary>
    [Serializable]
    public sealed class FlowSettings
    {
        /// <summary>On when the section is given (and not <c>"enabled": false</c>).</summary>
        public bool On;

        /// <summary>Flow from step t to t + span (forward) and to t − span (backward).</summary>
        public bool Forward = true, Backward = true;

        /// <summary>The step spans of the frame pairs (default: the next step only).</summary>
        public int[] Spans = { 1 };

        /// <summary>3D scene flow in output units in the output frame, per pair.</summary>
        public bool SceneFlow = true;

        /// <summary>Long tracks: query frames (time step indices of each video); empty = no tracks.</summary>
        public int[] TrackQueryFrames = new int[0];

        /// <summary>Long tracks: every Nth pixel (x and y) of a query frame that sees the target is a query point.</summary>
        public int TrackStride = 8;

        public bool Enabled => On;

        public FlowSettings Clone()
        {
            var copy = (FlowSettings)MemberwiseClone();
            copy.Spans = (int[])Spans?.Clone();
            copy.TrackQueryFrames = (int[])TrackQueryFrames?.Clone();
            return copy;
        }
    }
}
