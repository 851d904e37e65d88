using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>One frame of a <see cref="FlowVideo"/>: the dataset view and the geometry pack step whose mesh it sees.</summary>
    public sealed class FlowVideoFrame
    {
        public FlowVideoFrame(ExportFrame frame, int step, string meshFile)
        {
            Frame = frame;
            Step = step;
            MeshFile = meshFile;
        }

        public ExportFrame Frame { get; }

        /// <summary>The time step (index into the geometry pack's steps).</summary>
        public int Step { get; }

        /// <summary>The step's mesh, relative to the dataset ('/').</summary>
        public string MeshFile { get; }
    }

    /// <summary>
    /// A sequence of views of one camera path in time order, the unit flow is computed within: a monocular capture's train
    /// split (one view per step), or one camera of a multi-view capture's split (every step). Frame positions (0, 1, …)
    /// name the flow files (<see cref="FlowLayout"/>).
    /// </summary>
    public sealed class FlowVideo
    {
        public FlowVideo(string name, string split, int? cameraId, IReadOnlyList<FlowVideoFrame> frames)
        {
            Name = name;
            Split = split;
            CameraId = cameraId;
            Frames = frames;
        }

        public string Name { get; }
        public string Split { get; }

        /// <summary>The frames' <c>camera_id</c> (multi-view), null for a monocular video.</summary>
        public int? CameraId { get; }

        public IReadOnlyList<FlowVideoFrame> Frames { get; }
    }
}
