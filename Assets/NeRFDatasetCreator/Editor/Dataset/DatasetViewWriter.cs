using System.Collections.Generic;
using NerfDatasetCreator.Editor.Capture;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The capture's worker-thread writer for datasets: wraps a view's readback arrays as Core's raw frames (no copy),
    /// marks its normals as Unity world normals (the encoders relabel them into the output world as they read them),
    /// and hands it to Core's <see cref="ViewFileWriter"/> — through a lens capture's <see cref="LensResampler"/> first
    /// (the wide render becomes the distorted frame; everything after it is unchanged).
    /// The consumer releases the view afterwards.
    /// </summary>
    sealed class DatasetViewWriter : IViewWriter
    {
        readonly IReadOnlyList<PlannedView> _views;
        readonly ViewFileWriter _files;
        readonly LensResampler _lens;

        /// <param name="views">The planned views in the order their poses were given to the capture.</param>
        /// <param name="lens">The plan's resampler (<see cref="LensCapture.ResamplerFor"/>), or null without a lens.</param>
        public DatasetViewWriter(IReadOnlyList<PlannedView> views, ViewFileWriter files, LensResampler lens = null)
        {
            _views = views;
            _files = files;
            _lens = lens;
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
            if (_lens != null)
            {
                // Stage 2 of the per-view stages (parallel.md): the wide frame resampled into the distorted one, on this worker thread.
                // Into this worker thread's reused arrays: the frames are written out below, before the thread's next view.
                var distorted = _lens.Resample(colour, reuseThreadBuffers: true);
                data = ReferenceEquals(data, colour) ? distorted : _lens.Resample(data, reuseThreadBuffers: true);
                colour = distorted;
            }
            _files.Write(_views[view.ViewIndex], colour, data);
        }
    }
}
