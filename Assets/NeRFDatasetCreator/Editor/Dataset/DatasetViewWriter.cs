using System.Collections.Generic;
using NerfDatasetCreator.Editor.Capture;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The capture's worker-thread writer for datasets: wraps a view's readback arrays as Core's raw frames (no copy),
    /// marks its normals as Unity world normals (the encoders relabel them into the output world as they read them),
    /// and hands it to Core's <see cref="ViewFileWriter"/>.
    /// The consumer releases the view afterwards.
    /// </summary>
    sealed class DatasetViewWriter : IViewWriter
    {
        readonly IReadOnlyList<PlannedView> _views;
        readonly ViewFileWriter _files;

        /// <param name="views">The planned views in the order their poses were given to the capture.</param>
        public DatasetViewWriter(IReadOnlyList<PlannedView> views, ViewFileWriter files)
        {
            _views = views;
            _files = files;
        }

        public void Write(CapturedView view)
        {
            var colour = new RawFrame(view.Width, view.Height, view.Supersampling)
            {
                ColorOverBlack = view.ColorOverBlack,
                ColorOverWhite = view.ColorOverWhite,
                ColorIsGammaEncoded = view.ColorIsGammaEncoded,
                Mask = view.Mask,
                MaskBytesPerPixel = 1,
            };
            var atOutputSize = view.DataWidth != view.Width || view.DataHeight != view.Height;
            var data = atOutputSize ? new RawFrame(view.DataWidth, view.DataHeight, 1) : colour;
            data.Depth = view.Depth;
            data.Normals = view.Normal;
            // The normal pass writes Unity world normals; the encoders relabel them as they read them.
            data.NormalsInUnityWorld = true;
            if (view.BlurredOverBlack == null)
            {
                _files.Write(_views[view.ViewIndex], colour, data);
                return;
            }
            // Motion blur: the file_path image is the sub-frame average; the mid-pose render is the sharp image beside it.
            var blurred = new RawFrame(view.Width, view.Height, view.Supersampling)
            {
                ColorOverBlack = view.BlurredOverBlack,
                ColorOverWhite = view.BlurredOverWhite,
                ColorIsGammaEncoded = view.ColorIsGammaEncoded,
                Mask = view.Mask,
                MaskBytesPerPixel = 1,
            };
            if (!atOutputSize)
            {
                blurred.Depth = data.Depth;
                blurred.Normals = data.Normals;
                blurred.NormalsInUnityWorld = true;
                data = blurred;
            }
            _files.Write(_views[view.ViewIndex], blurred, data);
            _files.WriteSharp(_views[view.ViewIndex], colour);
        }
    }
}
