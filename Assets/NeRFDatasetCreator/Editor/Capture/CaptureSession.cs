using System;
using System.Collections.Generic;
using System.Diagnostics;
using UnityEditor;
using UnityEngine;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// One capture run: renders each pose's passes with one hidden camera into owned render textures, reads them back
    /// (several views in flight, waiting on the oldest) and hands each view to an <see cref="IViewConsumer"/> in order.
    /// Driven by <see cref="Step"/> so that it can run inside one call (CLI, tests) or a slice per editor update
    /// (<see cref="CaptureRunner"/>). <see cref="Dispose"/> always restores everything, after success, cancel or error.
    /// </summary>
    public sealed class CaptureSession : IDisposable
    {
        readonly GameObject _target;
        readonly string _targetName;
        readonly IReadOnlyList<UnityPose> _poses;
        readonly CaptureOptions _options;
        readonly CapturePasses _passes;
        readonly IViewConsumer _consumer;
        readonly ICaptureProgress _progress;
        readonly Stopwatch _clock = new Stopwatch();
        CaptureStage _stage;
        DataPassRenderer _dataPasses;
        RenderTargetSet[] _targets;
        ViewReadback[] _readbacks;
        SynchronousReadback _synchronous;
        SubFrameRenderer _subFrames;
        MaterialPassCapture _materialPasses;
        RelitColourRenderer _relit;
        // Issue 38: each view's material passes and relit colour pairs, read back at render time, by view index.
        readonly Dictionary<int, MaterialPassResult> _materialResults = new Dictionary<int, MaterialPassResult>();
        readonly Dictionary<int, Dictionary<string, ushort[][]>> _relitResults = new Dictionary<int, Dictionary<string, ushort[][]>>();
        // Motion blur: the averaged sub-frames of views whose readback is still pending, by view index.
        readonly Dictionary<int, ushort[][]> _blurred = new Dictionary<int, ushort[][]>();
        CapturePools _pools;
        CaptureEditorState _editorState;
        bool _cancelRequested;
        bool _stepping;
        string _interruption;
        bool _finished;
        bool _disposed;
        int _nextView;
        int _delivered;

        CaptureSession(GameObject target, IReadOnlyList<UnityPose> poses, CaptureOptions options, IViewConsumer consumer,
            ICaptureProgress progress)
        {
            _target = target;
            _targetName = target == null ? "" : target.name;
            _poses = poses;
            _options = options;
            _passes = options.EffectivePasses;
            _consumer = consumer;
            _progress = progress;
            Meter = new ThroughputMeter(poses.Count);
        }

        /// <summary>
        /// Checks everything that can be checked before touching the GPU, then sets up the preview scene, camera,
        /// render textures and readback ring. Throws <see cref="InvalidParameterException"/> for bad options and
        /// <see cref="CaptureException"/> when this editor or this target cannot be captured; nothing is left behind.
        /// </summary>
        public static CaptureSession Begin(GameObject target, IReadOnlyList<UnityPose> poses, CaptureOptions options,
            IViewConsumer consumer, ICaptureProgress progress = null)
        {
            if (options == null) throw new ArgumentNullException(nameof(options));
            if (poses == null) throw new ArgumentNullException(nameof(poses));
            if (consumer == null) throw new ArgumentNullException(nameof(consumer));
            options.ThrowIfInvalid();
            if (poses.Count == 0)
                throw new InvalidParameterException(new[] { new ValidationProblem("capture.poses", "0", "has no views to render.", "Plan at least one view.") });
            InvalidParameterException.ThrowIfAny(PoseProblem(poses));
            CaptureEnvironment.ThrowIfCannotRender(options.EffectivePasses);
            CheckTarget(target, options.Isolation);
            if (EditorApplication.isPlayingOrWillChangePlaymode)
                throw new CaptureException("Unity is in (or entering) Play mode. Stop Play mode, then capture.");
            ActiveCapture.ThrowIfBusy();

            var session = new CaptureSession(target, poses, options, consumer, progress);
            // From here until Dispose this is the editor's one capture, and Play mode, reloads and quitting end it.
            ActiveCapture.Claim(session);
            try
            {
                session.SetUp();
                return session;
            }
            catch
            {
                session.Dispose();
                throw;
            }
        }

        public int Total => _poses.Count;

        /// <summary>The target's name when the capture began (for messages; the object may be gone since).</summary>
        public string TargetName => _targetName;
        public int Delivered => _delivered;
        public bool IsFinished => _finished;
        public ThroughputMeter Meter { get; }

        /// <summary>True when views were read back with AsyncGPUReadback, false on the ReadPixels fallback.</summary>
        public bool UsesAsyncReadback { get; private set; }

        /// <summary>The vertical FOV (degrees) the images were rendered with: the template camera's when one was given.</summary>
        public double VerticalFieldOfViewDegrees { get; private set; }

        /// <summary>Non-mesh renderers (particles, lines, sprites) and terrains left out of the mask, depth and normal passes.</summary>
        public int UnsupportedRendererCount => _stage == null ? 0 : _stage.UnsupportedRendererCount;

        /// <summary>Asks the run to stop; the next <see cref="Step"/> throws <see cref="CaptureCancelledException"/>.</summary>
        public void Cancel() => _cancelRequested = true;

        /// <summary>
        /// Set by a driver that steps the session across editor updates (<see cref="CaptureRunner.RunInBackground"/>):
        /// called by <see cref="Interrupt"/> with the exception to end the run with; it must dispose the session.
        /// </summary>
        internal Action<CaptureCancelledException> Interrupted;

        /// <summary>
        /// Ends the run at once because the editor is about to enter Play mode, reload scripts or quit
        /// (<see cref="ActiveCapture"/>). Between steps the session is disposed before this returns (through its
        /// driver's <see cref="Interrupted"/>, which also reports the result). From inside <see cref="Step"/> (an event
        /// raised while the blocking run draws its progress bar) it only marks the run: Step throws at its next check
        /// and its caller disposes right after, still before control returns to the editor.
        /// </summary>
        internal void Interrupt(string reason)
        {
            if (_disposed) return;
            if (_interruption == null) _interruption = reason;
            if (_stepping) return;
            try
            {
                Interrupted?.Invoke(new CaptureCancelledException(_interruption));
            }
            finally
            {
                Dispose(); // already done by the driver; without one, nothing else would
            }
        }

        /// <summary>The first pose that is not finite or whose rotation is not a unit quaternion, or null.</summary>
        static ValidationProblem PoseProblem(IReadOnlyList<UnityPose> poses)
        {
            for (var i = 0; i < poses.Count; i++)
            {
                var p = poses[i].Position;
                var q = poses[i].Rotation;
                var finite = !double.IsNaN(p.X + p.Y + p.Z + q.X + q.Y + q.Z + q.W) &&
                             !double.IsInfinity(p.X + p.Y + p.Z + q.X + q.Y + q.Z + q.W);
                if (!finite || Math.Abs(q.Norm - 1) > 1e-6)
                    return new ValidationProblem("capture.poses[" + i + "]", "position " + p + ", rotation " + q,
                        finite ? "has a rotation quaternion that is not of unit length." : "is not finite.",
                        "Recompute the camera plan; poses come from the formation settings.");
            }
            return null;
        }

        internal static void CheckTarget(GameObject target, CaptureIsolation isolation)
        {
            if (isolation == CaptureIsolation.WholeScene) return;
            if (target == null)
                throw new CaptureException("No target is set (or it was deleted). Pick the GameObject to capture.");
            if (EditorUtility.IsPersistent(target))
                throw new CaptureException("The target '" + target.name + "' is a prefab or model asset, not an object in the scene. " +
                    "Drag it into the scene and pick that instance.");
            foreach (var _ in TargetMeshes.Of(target)) return;
            throw new CaptureException("The target '" + target.name + "' has no enabled MeshRenderer or SkinnedMeshRenderer with " +
                "a mesh on itself or its active children, so there is nothing to capture. Pick the object that holds the model's renderers.");
        }

        void SetUp()
        {
            _editorState = new CaptureEditorState();
            _editorState.LockReload();
            _editorState.CompileShadersSynchronously();

            _stage = new CaptureStage(_target, _options);
            _dataPasses = new DataPassRenderer(_stage.DataPassRenderers, _stage.Camera.cullingMask,
                (_passes & CapturePasses.Labels) != 0 ? _stage.CopyLabels : null);
            VerticalFieldOfViewDegrees = _stage.Camera.fieldOfView;

            UsesAsyncReadback = SystemInfo.supportsAsyncGPUReadback && !_options.ForceSynchronousReadback;
            var inFlight = UsesAsyncReadback ? _options.ReadbacksInFlight : 1;
            _targets = new RenderTargetSet[inFlight];
            _readbacks = new ViewReadback[inFlight];
            for (var i = 0; i < inFlight; i++)
            {
                _targets[i] = new RenderTargetSet(_options, _passes, i);
                _readbacks[i] = new ViewReadback();
            }
            if (!UsesAsyncReadback) _synchronous = new SynchronousReadback();
            if (_options.SubFramesOf != null) _subFrames = new SubFrameRenderer(_options, UsesAsyncReadback);
            if (_options.MaterialPasses != null && _options.MaterialPasses.Count > 0)
                _materialPasses = new MaterialPassCapture(_stage.DataPassRenderers, _stage.Camera.cullingMask, _options.MaterialPasses,
                    _options.SupersampledWidth, _options.SupersampledHeight);
            if (_options.Relighting != null && _options.Relighting.Count > 0 && (_passes & CapturePasses.Color) != 0)
                _relit = new RelitColourRenderer(_stage, _options, _options.Relighting);
            // Enough arrays for the views in flight plus what a consumer's queue and workers typically hold.
            _pools = new CapturePools(_options, inFlight + 2 * Environment.ProcessorCount + 2);
            _clock.Start();
        }

        /// <summary>
        /// Renders views until about <paramref name="budgetSeconds"/> have passed (at least one view), reports progress
        /// and returns true while views remain. The last call drains the readbacks and calls the consumer's Finish.
        /// Throws <see cref="CaptureCancelledException"/> after a cancel and <see cref="CaptureException"/> on failure;
        /// the caller then disposes the session, which restores everything and aborts the consumer.
        /// </summary>
        public bool Step(double budgetSeconds)
        {
            if (_disposed)
            {
                if (_interruption != null) throw new CaptureCancelledException(_interruption);
                throw new ObjectDisposedException(nameof(CaptureSession));
            }
            if (_finished) return false;
            var sliceStart = _clock.Elapsed.TotalSeconds;
            var previousActive = RenderTexture.active;
            _stepping = true;
            try
            {
                do
                {
                    ThrowIfCancelledOrBroken();
                    if (_nextView < _poses.Count)
                    {
                        RenderView(_nextView);
                        _nextView++;
                    }
                    else
                    {
                        DrainAll();
                        _consumer.Finish();
                        _finished = true;
                    }
                    Meter.Update(_delivered, _clock.Elapsed.TotalSeconds);
                    _progress?.Report(Meter);
                } while (!_finished && _clock.Elapsed.TotalSeconds - sliceStart < budgetSeconds);
            }
            finally
            {
                _stepping = false;
                RenderTexture.active = previousActive;
            }
            if (_finished) _clock.Stop();
            return !_finished;
        }

        void ThrowIfCancelledOrBroken()
        {
            if (_interruption != null) throw new CaptureCancelledException(_interruption);
            if (_cancelRequested || (_progress != null && _progress.CancelRequested))
                throw new CaptureCancelledException();
            if (_options.Isolation == CaptureIsolation.TargetOnly && _target == null)
                throw new CaptureException("The target '" + _targetName + "' was deleted during the capture. The capture stopped; " +
                    "no dataset was written.");
            if (!_stage.IsIntact)
                throw new CaptureException("The capture's preview scene was destroyed from outside (a scene reload or a script). " +
                    "The capture stopped; no dataset was written.");
        }

        void RenderView(int index)
        {
            var slot = index % _targets.Length;
            var readback = _readbacks[slot];
            if (readback.IsPending) Deliver(readback); // the oldest view in flight: its textures are about to be reused

            var pose = _poses[index];
            var camera = _stage.Camera;
            var targets = _targets[slot];
            // Motion blur: the sub-frames first, in the view's own textures; the mid-pose render below overwrites them.
            var subFrames = _options.SubFramesOf?.Invoke(index);
            if (subFrames != null && subFrames.Count > 0 && targets.ColorOverBlack != null)
            {
                _stage.PinLighting();
                try
                {
                    // The averaged pair goes into pooled arrays (returned with the view, CapturePools.Return), written by
                    // the sum's worker while the mid-pose render below runs; Hand waits for it.
                    var black = _pools.Color.Rent();
                    var white = _pools.Color.Rent();
                    _blurred[index] = new[] { black, white };
                    _subFrames.Render(_stage.Root, camera, targets, subFrames, QualitySettings.activeColorSpace == ColorSpace.Gamma, black, white);
                }
                finally
                {
                    _stage.UnpinLighting();
                }
            }
            _options.BeforeView?.Invoke(_stage.Root, index);
            pose.ApplyTo(camera.transform);

            _stage.PinLighting();
            try
            {
                RenderColour(camera, targets);
            }
            finally
            {
                _stage.UnpinLighting();
            }
            // The data passes draw outside the camera's render loop, so no pipeline setting can change them. What they
            // draw is decided per view, as the camera's culling decides it: BeforeView may have switched renderers.
            if (targets.Mask != null || targets.Depth != null || targets.Normal != null || targets.Labels != null) _dataPasses.PrepareView();
            if (targets.Mask != null) _dataPasses.Render(camera, targets.Mask, DataPassRenderer.MaskPass);
            if (targets.Depth != null) _dataPasses.Render(camera, targets.Depth, DataPassRenderer.DepthPass);
            if (targets.Normal != null) _dataPasses.Render(camera, targets.Normal, DataPassRenderer.NormalPass);
            if (targets.Labels != null) _dataPasses.Render(camera, targets.Labels, DataPassRenderer.LabelPass);
            // Issue 38: read back at once (synchronously), before the camera moves on; attached to the view in Hand.
            if (_materialPasses != null) _materialResults[index] = _materialPasses.Render(camera);
            if (_relit != null) _relitResults[index] = _relit.Render(camera, _pools.Color);

            if (UsesAsyncReadback)
            {
                readback.Request(index, pose, targets);
            }
            else
            {
                var view = NewView(index, pose);
                try
                {
                    _synchronous.ReadInto(targets, view, _pools);
                }
                catch
                {
                    view.Release();
                    throw;
                }
                Hand(view);
            }
        }

        /// <summary>Sub-frames rendered for motion blur so far.</summary>
        public int SubFramesRendered => _subFrames?.Rendered ?? 0;

        internal static void RenderColour(Camera camera, RenderTargetSet targets)
        {
            if (targets.ColorOverBlack == null) return;
            if (camera.clearFlags == CameraClearFlags.Skybox)
            {
                // An opaque sky (CaptureOptions.Skybox; CaptureStage sets these clear flags only then): the background
                // colour is not drawn, so a second render would be the same image. Render once and copy it, exactly,
                // as the other half: K = W gives alpha 1 and colour K in every sample (DifferenceMattingTests.
                // ASkyRenderUsedAsBothHalvesIsOpaqueEverywhereEvenWhereItIsBlack). Same size and format: CopyTexture's
                // requirements (Scripting API Graphics.CopyTexture); without copy support, render it twice.
                Render(camera, targets.ColorOverBlack, OverBlack);
                if (SystemInfo.copyTextureSupport != UnityEngine.Rendering.CopyTextureSupport.None)
                    Graphics.CopyTexture(targets.ColorOverBlack, targets.ColorOverWhite);
                else
                    Render(camera, targets.ColorOverWhite, OverWhite);
                camera.targetTexture = null;
                return;
            }
            // Difference matting: the same colour pass over two clears; Core solves alpha and colour from the pair.
            // Black and white are fixed points of the sRGB curve, so URP's conversion of the background colour
            // to the active colour space (URP 14 UniversalRenderPipeline.cs:1333) leaves them as they are.
            Render(camera, targets.ColorOverBlack, OverBlack);
            Render(camera, targets.ColorOverWhite, OverWhite);
            camera.backgroundColor = OverBlack;
            camera.targetTexture = null;
        }

        // The alpha of the clear colour is irrelevant: the matting reads RGB only.
        static readonly Color OverBlack = new Color(0f, 0f, 0f, 0f);
        static readonly Color OverWhite = new Color(1f, 1f, 1f, 0f);

        static void Render(Camera camera, RenderTexture target, Color clear)
        {
            camera.backgroundColor = clear;
            camera.targetTexture = target;
            camera.Render();
        }

        void DrainAll()
        {
            // Oldest first: the slot after the last one written holds the oldest pending view.
            for (var i = 0; i < _readbacks.Length; i++)
            {
                var readback = _readbacks[(_nextView + i) % _readbacks.Length];
                if (readback.IsPending) Deliver(readback);
            }
        }

        void Deliver(ViewReadback readback)
        {
            var view = NewView(readback.ViewIndex, readback.Pose);
            try
            {
                readback.CompleteInto(view, _pools);
            }
            catch
            {
                view.Release();
                throw;
            }
            Hand(view);
        }

        CapturedView NewView(int index, UnityPose pose) => new CapturedView(index, pose,
            _options.SupersampledWidth, _options.SupersampledHeight, _options.Supersampling,
            _options.DataWidth, _options.DataHeight, _pools.ReturnCallback)
        {
            ColorIsGammaEncoded = QualitySettings.activeColorSpace == ColorSpace.Gamma,
        };

        void Hand(CapturedView view)
        {
            if (_blurred.TryGetValue(view.ViewIndex, out var blurred))
            {
                _subFrames.WaitForAverage(); // the latest view's average, so this one's too (one sum, jobs in order)
                _blurred.Remove(view.ViewIndex);
                view.BlurredOverBlack = blurred[0];
                view.BlurredOverWhite = blurred[1];
            }
            if (_materialResults.TryGetValue(view.ViewIndex, out var materials))
            {
                _materialResults.Remove(view.ViewIndex);
                view.Materials = materials;
            }
            if (_relitResults.TryGetValue(view.ViewIndex, out var relit))
            {
                _relitResults.Remove(view.ViewIndex);
                view.Relit = relit;
            }
            _consumer.Consume(view);
            _delivered++;
        }

        /// <summary>What a finished run reports and a dataset's provenance records.</summary>
        public CaptureSummary Summary => new CaptureSummary(
            _delivered, _clock.Elapsed.TotalSeconds, Meter.ViewsPerSecond, VerticalFieldOfViewDegrees,
            CaptureEnvironment.RenderPipelineName, QualitySettings.activeColorSpace.ToString(), UsesAsyncReadback,
            Application.unityVersion, SystemInfo.graphicsDeviceType.ToString(), UnsupportedRendererCount)
        {
            Materials = _materialPasses == null ? null
                : new MaterialShaderReport(_materialPasses.Pipeline, _materialPasses.SupportedShaders, _materialPasses.UnsupportedShaders),
        };

        /// <summary>Releases everything the run created and, unless it finished, aborts the consumer. Never throws.</summary>
        public void Dispose()
        {
            if (_disposed) return;
            _disposed = true;
            if (!_finished) Try(_consumer.Abort);
            if (_readbacks != null)
                foreach (var readback in _readbacks)
                    readback?.Forget();
            // Let the GPU finish reading the textures before they are destroyed. Unconditionally: CompleteInto clears
            // IsPending before it waits, so after an exception part-way through a view its other requests may still be
            // in flight. WaitAllRequests (UnityCsReference 2022.3 Runtime/Export/Graphics/AsyncGPUReadback.bindings.cs:126,
            // 6000.0 :132) returns at once when none is.
            if (UsesAsyncReadback) Try(UnityEngine.Rendering.AsyncGPUReadback.WaitAllRequests);
            if (_targets != null)
                foreach (var set in _targets)
                    if (set != null) Try(set.Dispose);
            if (_synchronous != null) Try(_synchronous.Dispose);
            if (_subFrames != null) Try(_subFrames.Dispose);
            if (_materialPasses != null) Try(_materialPasses.Dispose);
            if (_relit != null) Try(_relit.Dispose);
            if (_stage != null) Try(_stage.Dispose);
            if (_dataPasses != null) Try(_dataPasses.Dispose);
            _editorState?.Restore();
            _clock.Stop();
            ActiveCapture.Release(this);
        }

        static void Try(Action action)
        {
            try
            {
                action();
            }
            catch (Exception e)
            {
                // Cleanup must go on; the original error (if any) is what the user needs to see.
                UnityEngine.Debug.LogException(e);
            }
        }
    }
}
