using System;
using System.Collections.Generic;
using UnityEngine;
using UnityEngine.Rendering;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Motion blur's sub-frame loop (Core's <see cref="SubFrameSchedule"/>, Documentation~/motion-blur.md): for one view,
    /// each sub-frame poses the content (<see cref="CaptureOptions.BeforeSubFrame"/>: the dynamic capture's ContentClock at
    /// the sub-frame's time) and the camera, renders the colour pair into the view's own render textures and reads it
    /// back at once, and Core's sub-frame average (<see cref="ViewPipeline.SubFrameAverage"/>, the pipeline's first stage) adds it
    /// in linear light. The view's mid-pose render
    /// (colour for the sharp image, and the data passes) follows in the same textures, so the sub-frames need no
    /// textures of their own.
    /// <para>
    /// Unity behaviour relied on: <c>Camera.Render()</c> renders with the camera's transform as it is at the call
    /// (Scripting API Camera.Render; the camera is disabled, CaptureStage.ConfigureCamera, so nothing else renders it), so
    /// moving the transform between calls gives one render per pose; <c>AsyncGPUReadbackRequest.WaitForCompletion</c>
    /// (UnityCsReference 2022.3 Runtime/Export/Graphics/AsyncGPUReadback.bindings.cs) makes the read synchronous, which
    /// the sub-frames need because the next one overwrites the same texture; content posed by ContentClock is evaluated
    /// from scratch at each time (Editor/Time/ContentClock.cs), so sub-frames at arbitrary times are exact.
    /// </para>
    /// </summary>
    sealed class SubFrameRenderer : IDisposable
    {
        readonly CaptureOptions _options;
        readonly SynchronousReadback _fallback;
        ushort[] _black, _white;

        public SubFrameRenderer(CaptureOptions options, bool asyncReadback)
        {
            _options = options;
            if (!asyncReadback) _fallback = new SynchronousReadback();
        }

        /// <summary>Sub-frames rendered so far (all views).</summary>
        public int Rendered { get; private set; }

        /// <summary>Renders <paramref name="subFrames"/> and returns the averaged colour pair (new arrays: the view keeps them).</summary>
        public void Render(GameObject root, Camera camera, RenderTargetSet targets, IReadOnlyList<SubFrame> subFrames, bool gammaEncoded,
            out ushort[] overBlack, out ushort[] overWhite)
        {
            int w = _options.SupersampledWidth, h = _options.SupersampledHeight;
            var accumulator = ViewPipeline.SubFrameAverage(w, h, subFrames.Count, _options.RollingShutterReadout, gammaEncoded);
            foreach (var sub in subFrames)
            {
                sub.Pose.ApplyTo(camera.transform);
                _options.BeforeSubFrame?.Invoke(root, sub, camera.transform);
                CaptureSession.RenderColour(camera, targets);
                Read(targets, w * h * 4);
                accumulator.Add(sub.Index, _black, _white);
                Rendered++;
            }
            overBlack = new ushort[w * h * 4];
            overWhite = new ushort[w * h * 4];
            accumulator.Finish(overBlack, overWhite);
        }

        void Read(RenderTargetSet targets, int length)
        {
            if (_black == null || _black.Length != length)
            {
                _black = new ushort[length];
                _white = new ushort[length];
            }
            if (_fallback != null)
            {
                _fallback.ReadColour(targets, _black, _white);
                return;
            }
            Copy(AsyncGPUReadback.Request(targets.ColorOverBlack, 0, targets.ColorOverBlack.graphicsFormat), _black);
            Copy(AsyncGPUReadback.Request(targets.ColorOverWhite, 0, targets.ColorOverWhite.graphicsFormat), _white);
        }

        static void Copy(AsyncGPUReadbackRequest request, ushort[] into)
        {
            request.WaitForCompletion();
            if (request.hasError)
                throw new CaptureException("The GPU readback of a motion blur sub-frame failed. Try again with synchronous readback (CaptureOptions.ForceSynchronousReadback).");
            var data = request.GetData<ushort>();
            if (data.Length != into.Length)
                throw new CaptureException("A sub-frame readback returned " + data.Length + " values where " + into.Length + " were expected.");
            data.CopyTo(into);
        }

        public void Dispose() => _fallback?.Dispose();
    }
}
