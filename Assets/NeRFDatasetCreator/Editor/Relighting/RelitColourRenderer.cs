using System;
using System.Collections.Generic;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// Renders a view's colour pair (over black and over white, the difference-matting pair) once per relighting render
    /// (issue 38), in its own render textures, and reads it back synchronously. Each render switches the capture's
    /// lighting with <see cref="LightingSwitch"/> inside the preview-scene lighting override and switches it back before
    /// the next, even when rendering throws; the camera, its pose and the data passes are those of the view.
    /// </summary>
    sealed class RelitColourRenderer : IDisposable
    {
        readonly CaptureStage _stage;
        readonly IReadOnlyList<UnityLightingRender> _renders;
        RenderTargetSet _targets;
        SynchronousReadback _readback;

        public RelitColourRenderer(CaptureStage stage, CaptureOptions options, IReadOnlyList<UnityLightingRender> renders)
        {
            _stage = stage;
            _renders = renders;
            try
            {
                _targets = new RenderTargetSet(options, CapturePasses.Color, 100);
                _readback = new SynchronousReadback();
            }
            catch
            {
                Dispose();
                throw;
            }
        }

        /// <summary>
        /// The colour pair of the camera's current view under each render, by file key: [over black, over white], half-float
        /// RGBA, in arrays rented from <paramref name="pool"/> (the capture's colour pool: <see cref="CapturePools.Return"/>
        /// gives them back with the view, so a relit capture makes no more garbage per view than a plain one).
        /// </summary>
        public Dictionary<string, ushort[][]> Render(Camera camera, ExactArrayPool<ushort> pool)
        {
            var result = new Dictionary<string, ushort[][]>(StringComparer.Ordinal);
            var lights = _stage.Lights;
            var range = RangeFor(_stage.DataPassRenderers);
            foreach (var render in _renders)
            {
                var black = pool.Rent();
                var white = pool.Rent();
                _stage.PinLighting();
                try
                {
                    using (LightingSwitch.Apply(render, lights, _stage.Root.transform, range(render)))
                        CaptureSession.RenderColour(camera, _targets);
                }
                finally
                {
                    _stage.UnpinLighting();
                }
                _readback.ReadColour(_targets, black, white);
                result[render.Key] = new[] { black, white };
            }
            return result;
        }

        /// <summary>A point or spot light's range: from the light past the far side of everything drawn, so that it reaches all of it.</summary>
        static Func<UnityLightingRender, float> RangeFor(IReadOnlyList<Renderer> renderers)
        {
            Bounds? all = null;
            foreach (var r in renderers)
            {
                if (r == null) continue;
                if (all == null) all = r.bounds;
                else
                {
                    var b = all.Value;
                    b.Encapsulate(r.bounds);
                    all = b;
                }
            }
            return render =>
            {
                if (all == null) return 100f;
                var p = new Vector3((float)render.Position.X, (float)render.Position.Y, (float)render.Position.Z);
                return Mathf.Max(1f, Vector3.Distance(p, all.Value.center) + 2f * all.Value.extents.magnitude);
            };
        }

        public void Dispose()
        {
            _targets?.Dispose();
            _targets = null;
            _readback?.Dispose();
            _readback = null;
        }
    }
}
