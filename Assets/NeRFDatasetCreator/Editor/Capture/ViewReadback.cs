using System;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Experimental.Rendering;
using UnityEngine.Rendering;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The pending GPU readbacks of one view (one per pass), and the copy of their bytes into pooled managed arrays.
    /// Data from <c>AsyncGPUReadbackRequest.GetData</c> is only valid for a frame, so it is copied out at once.
    /// </summary>
    sealed class ViewReadback
    {
        AsyncGPUReadbackRequest _black, _white, _mask, _depth, _normal, _labels;
        RenderTargetSet _targets;

        public int ViewIndex { get; private set; }
        public UnityPose Pose { get; private set; }
        public bool IsPending { get; private set; }

        public void Request(int viewIndex, UnityPose pose, RenderTargetSet targets)
        {
            ViewIndex = viewIndex;
            Pose = pose;
            _targets = targets;
            // dstFormat = the texture's own format: no conversion, and no sRGB decode of the colour bytes.
            if (targets.ColorOverBlack != null)
            {
                _black = AsyncGPUReadback.Request(targets.ColorOverBlack, 0, targets.ColorOverBlack.graphicsFormat);
                _white = AsyncGPUReadback.Request(targets.ColorOverWhite, 0, targets.ColorOverWhite.graphicsFormat);
            }
            if (targets.Mask != null) _mask = AsyncGPUReadback.Request(targets.Mask, 0, targets.Mask.graphicsFormat);
            if (targets.Depth != null) _depth = AsyncGPUReadback.Request(targets.Depth, 0, targets.Depth.graphicsFormat);
            if (targets.Normal != null) _normal = AsyncGPUReadback.Request(targets.Normal, 0, targets.Normal.graphicsFormat);
            if (targets.Labels != null) _labels = AsyncGPUReadback.Request(targets.Labels, 0, targets.Labels.graphicsFormat);
            IsPending = true;
        }

        /// <summary>Waits for this view's readbacks (the oldest in flight) and copies them into <paramref name="view"/>.</summary>
        public void CompleteInto(CapturedView view, CapturePools pools)
        {
            IsPending = false;
            if (_targets.ColorOverBlack != null)
            {
                // Half floats, copied as their 16-bit patterns; Core decodes them.
                view.ColorOverBlack = Copy<ushort>(_black, pools.Color, "colour (over black)");
                view.ColorOverWhite = Copy<ushort>(_white, pools.Color, "colour (over white)");
            }
            if (_targets.Mask != null)
                view.Mask = _targets.Mask.graphicsFormat == GraphicsFormat.R8_UNorm
                    ? Copy<byte>(_mask, pools.Mask, "mask")
                    : RedChannel(Wait(_mask, "mask").GetData<byte>(), pools.Mask);
            if (_targets.Depth != null)
                view.Depth = Copy<float>(_depth, pools.Depth, "depth");
            if (_targets.Normal != null)
                view.Normal = Copy<float>(_normal, pools.Normal, "normal");
            if (_targets.Labels != null)
                view.Labels = Copy<byte>(_labels, pools.Labels, "labels");
            _targets = null;
        }

        /// <summary>Drops the pending requests without reading them (cancel, failure).</summary>
        public void Forget()
        {
            IsPending = false;
            _targets = null;
        }

        static AsyncGPUReadbackRequest Wait(AsyncGPUReadbackRequest request, string pass)
        {
            // Edit and batch mode do not tick readbacks every frame; waiting on the request drives it to completion.
            request.WaitForCompletion();
            if (request.hasError)
                throw new CaptureException("The GPU readback of the " + pass + " pass failed. Try again with fewer readbacks " +
                    "in flight or with synchronous readback (CaptureOptions.ForceSynchronousReadback).");
            return request;
        }

        static T[] Copy<T>(AsyncGPUReadbackRequest request, ExactArrayPool<T> pool, string pass) where T : struct
        {
            var data = Wait(request, pass).GetData<T>();
            return CopyExact(data, pool, pass);
        }

        internal static T[] CopyExact<T>(NativeArray<T> data, ExactArrayPool<T> pool, string pass) where T : struct
        {
            if (data.Length != pool.Length)
                throw new CaptureException("The " + pass + " readback returned " + data.Length + " values where " + pool.Length +
                    " were expected (a padded row layout?). Please report this with your Unity version and graphics API (" +
                    SystemInfo.graphicsDeviceType + ").");
            var array = pool.Rent();
            NativeArray<T>.Copy(data, 0, array, 0, array.Length);
            return array;
        }

        /// <summary>The red byte of each RGBA8 pixel: the mask when R8 cannot be rendered to.</summary>
        internal static byte[] RedChannel(NativeArray<byte> rgba, ExactArrayPool<byte> pool)
        {
            if (rgba.Length != pool.Length * 4)
                throw new CaptureException("The mask readback returned " + rgba.Length + " bytes where " + pool.Length * 4 +
                    " were expected. Please report this with your Unity version and graphics API (" + SystemInfo.graphicsDeviceType + ").");
            var array = pool.Rent();
            for (var i = 0; i < array.Length; i++) array[i] = rgba[i * 4];
            return array;
        }
    }
}
