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
    /// back at once into a reused input pair, and Core's sub-frame sum (<see cref="BackgroundSubFrameSum"/> around
    /// <see cref="ViewPipeline.SubFrameAverage"/>'s accumulator, the pipeline's first stage) adds it in linear light on its
    /// own worker thread while the next sub-frame renders. The view's mid-pose render
    /// (colour for the sharp image, and the data passes) follows in the same textures, so the sub-frames need no
    /// textures of their own.
    /// <para>
    /// Unity behaviour relied on: <c>Camera.Render()</c> renders with the camera's transform as it is at the call
    /// (Scripting API Camera.Render; the camera is disabled, CaptureStage.ConfigureCamera, so nothing else renders it), so
    /// moving the transform between calls gives one render per pose; <c>AsyncGPUReadbackRequest.WaitForCompletion</c>
    /// (UnityCsReference 2022.3 Runtime/Export/Graphics/AsyncGPUReadback.bindings.cs) makes the read synchronous, which
    /// the sub-frames need because the next one overwrites the same texture; content posed by ContentClock is evaluated
    /// from scratch at each time (Editor/Time/ContentClock.cs), so sub-frames at arbitrary times are exact. The worker
    /// thread calls only Core (no Unity API); the readback's <c>NativeArray</c> is copied into the input pair on the main
    /// thread (<c>NativeArray.CopyTo(T[])</c>) before the request is dropped, so no Unity memory crosses threads.
    /// </para>
    /// </summary>
    sealed class SubFrameRenderer : IDisposable
    {
        readonly CaptureOptions _options;
        readonly SynchronousReadback _fallback;
        BackgroundSubFrameSum _sum;
        bool _sumIsGamma;

        public SubFrameRenderer(CaptureOptions options, bool asyncReadback)
        {
            _options = options;
            if (!asyncReadback) _fallback = new SynchronousReadback();
        }

        /// <summary>Sub-frames rendered so far (all views).</summary>
        public int Rendered { get; private set; }

        /// <summary>
        /// Renders <paramref name="subFrames"/> and has their average written into <paramref name="overBlack"/> and
        /// <paramref name="overWhite"/> (the view keeps them) by Core's <see cref="BackgroundSubFrameSum"/>: each readback is
        /// copied into one of its two reused input pairs and summed on its worker thread while the next sub-frame renders
        /// (issue 32, R4-2). Returns before the average is written: call <see cref="WaitForAverage"/> before reading it.
        /// </summary>
        public void Render(GameObject root, Camera camera, RenderTargetSet targets, IReadOnlyList<SubFrame> subFrames, bool gammaEncoded,
            ushort[] overBlack, ushort[] overWhite)
        {
            int w = _options.SupersampledWidth, h = _options.SupersampledHeight;
            if (_sum == null || _sumIsGamma != gammaEncoded)
            {
                // One per capture (the colour space does not change during one): its sums are allocated once.
                _sum?.Dispose();
                _sum = new BackgroundSubFrameSum(w, h, _options.RollingShutterReadout, gammaEncoded);
                _sumIsGamma = gammaEncoded;
            }
            try
            {
                _sum.Begin(subFrames.Count);
                foreach (var sub in subFrames)
                {
                    sub.Pose.ApplyTo(camera.transform);
                    _options.BeforeSubFrame?.Invoke(root, sub, camera.transform);
                    CaptureSession.RenderColour(camera, targets);
                    var input = _sum.TakeInput(out var black, out var white);
                    Read(targets, black, white);
                    _sum.Add(input, sub.Index);
                    Rendered++;
                }
                _sum.Finish(overBlack, overWhite);
            }
            catch (SubFrameSumException e)
            {
                throw Failed(e);
            }
        }

        /// <summary>Waits until the last view's average is written (the worker's failure surfaces here as a <see cref="CaptureException"/>).</summary>
        public void WaitForAverage()
        {
            try
            {
                _sum?.WaitIdle();
            }
            catch (SubFrameSumException e)
            {
                throw Failed(e);
            }
        }

        static CaptureException Failed(SubFrameSumException e) => new CaptureException(e.Message + " The capture stopped; no dataset was written.");

        void Read(RenderTargetSet targets, ushort[] black, ushort[] white)
        {
            if (_fallback != null)
            {
                _fallback.ReadColour(targets, black, white);
                return;
            }
            Copy(AsyncGPUReadback.Request(targets.ColorOverBlack, 0, targets.ColorOverBlack.graphicsFormat), black);
            Copy(AsyncGPUReadback.Request(targets.ColorOverWhite, 0, targets.ColorOverWhite.graphicsFormat), white);
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

        public void Dispose()
        {
            _sum?.Dispose();
            _fallback?.Dispose();
        }
    }
}
