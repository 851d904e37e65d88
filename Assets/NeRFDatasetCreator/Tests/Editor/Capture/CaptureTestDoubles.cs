using System;
using System.Collections.Generic;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>A view's pixels copied out of the pooled arrays, so they can be inspected after the run.</summary>
    sealed class RecordedView
    {
        public int ViewIndex;
        public UnityPose Pose;
        public int Width, Height, DataWidth, DataHeight;
        public ushort[] OverBlack, OverWhite;
        public ushort[] BlurredOverBlack, BlurredOverWhite;
        public bool GammaEncoded;
        public byte[] Mask;
        public float[] Depth, Normal;
        public byte[] Labels;
        public MaterialPassResult Materials;
        public Dictionary<string, ushort[][]> Relit;

        /// <summary>The instance id of a sample of the labels pass (<see cref="RendererLabelIds.InstanceAt"/>).</summary>
        public int InstanceAt(int x, int y) => RendererLabelIds.InstanceAt(Labels, y * Width + x);

        public int ClassAt(int x, int y) => RendererLabelIds.ClassAt(Labels, y * Width + x);

        public byte MaskAt(int x, int y) => Mask[y * Width + x];
        public float DepthAt(int x, int y) => Depth[y * DataWidth + x];

        /// <summary>The colour render over black at a sample, as written by the shaders (linear, or gamma in a Gamma project).</summary>
        public float OverBlackAt(int x, int y, int channel) => HalfFloat.ToFloat(OverBlack[(y * Width + x) * 4 + channel]);

        public float OverWhiteAt(int x, int y, int channel) => HalfFloat.ToFloat(OverWhite[(y * Width + x) * 4 + channel]);

        /// <summary>A sample's alpha by difference matting: 1 − mean over RGB of (over white − over black).</summary>
        public float AlphaAt(int x, int y)
        {
            float t = 0;
            for (var c = 0; c < 3; c++) t += OverWhiteAt(x, y, c) - OverBlackAt(x, y, c);
            return 1f - t / 3f;
        }

        /// <summary>The 8-bit sRGB value of an opaque sample's colour (what the PNG stores where alpha is 1).</summary>
        public byte ColorAt(int x, int y, int channel)
        {
            var value = OverBlackAt(x, y, channel);
            return GammaEncoded ? (byte)Math.Round(Math.Max(0, Math.Min(1, value)) * 255) : Srgb.EncodeByteExact(value);
        }

        public Vector3d NormalAt(int x, int y, out float coverage)
        {
            var i = (y * DataWidth + x) * 4;
            coverage = Normal[i + 3];
            return new Vector3d(Normal[i], Normal[i + 1], Normal[i + 2]);
        }
    }

    /// <summary>Keeps copies of every view in memory and records how the run ended.</summary>
    sealed class RecordingConsumer : IViewConsumer
    {
        public readonly List<RecordedView> Views = new List<RecordedView>();
        public bool Finished;
        public bool Aborted;

        public void Consume(CapturedView view)
        {
            Views.Add(new RecordedView
            {
                ViewIndex = view.ViewIndex,
                Pose = view.Pose,
                Width = view.Width,
                Height = view.Height,
                DataWidth = view.DataWidth,
                DataHeight = view.DataHeight,
                OverBlack = (ushort[])view.ColorOverBlack?.Clone(),
                OverWhite = (ushort[])view.ColorOverWhite?.Clone(),
                BlurredOverBlack = (ushort[])view.BlurredOverBlack?.Clone(),
                BlurredOverWhite = (ushort[])view.BlurredOverWhite?.Clone(),
                GammaEncoded = view.ColorIsGammaEncoded,
                Mask = (byte[])view.Mask?.Clone(),
                Depth = (float[])view.Depth?.Clone(),
                Normal = (float[])view.Normal?.Clone(),
                Labels = (byte[])view.Labels?.Clone(),
                Materials = view.Materials,
                Relit = view.Relit,
            });
            view.Release();
        }

        public void Finish() => Finished = true;
        public void Abort() => Aborted = true;
    }

    /// <summary>No display; cancels or acts after a given number of reports.</summary>
    sealed class ScriptedProgress : ICaptureProgress
    {
        public int CancelAfterViews = int.MaxValue;
        public Action<ThroughputMeter> OnReport;
        public int Reports;
        public bool Closed;
        bool _cancel;

        public void Report(ThroughputMeter meter)
        {
            Reports++;
            OnReport?.Invoke(meter);
            if (meter.Done >= CancelAfterViews) _cancel = true;
        }

        public bool CancelRequested => _cancel;
        public void Close() => Closed = true;
    }
}
