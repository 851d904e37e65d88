using System;

namespace NerfDatasetCreator.Editor
{
    /// <summary>Pooled pixel arrays of one capture, one pool per pass, sized for its render targets.</summary>
    sealed class CapturePools
    {
        public CapturePools(CaptureOptions options, int retained)
        {
            var samples = options.SupersampledWidth * options.SupersampledHeight;
            var data = options.DataWidth * options.DataHeight;
            // Two colour renders per view (over black, over white): twice the retained count; four with motion blur (the
            // averaged pair too).
            // Relighting adds one pair per lighting render (RelitColourRenderer).
            var pairs = 1 + (options.SubFramesOf != null ? 1 : 0) + (options.Relighting?.Count ?? 0);
            Color = new ExactArrayPool<ushort>(samples * 4, Math.Min(1024, 2 * pairs * retained));
            Mask = new ExactArrayPool<byte>(samples, retained);
            Depth = new ExactArrayPool<float>(data, retained);
            Normal = new ExactArrayPool<float>(data * 4, retained);
            Labels = new ExactArrayPool<byte>(samples * 4, retained);
        }

        /// <summary>RGBA half floats (R16G16B16A16_SFloat), one array per colour render.</summary>
        public ExactArrayPool<ushort> Color { get; }
        public ExactArrayPool<byte> Mask { get; }
        public ExactArrayPool<float> Depth { get; }
        public ExactArrayPool<float> Normal { get; }

        /// <summary>4 bytes per sample (<see cref="CapturePasses.Labels"/>).</summary>
        public ExactArrayPool<byte> Labels { get; }

        /// <summary>The release callback of a <see cref="CapturedView"/>: returns its arrays. Runs on any thread.</summary>
        public void Return(CapturedView view)
        {
            Color.Return(view.ColorOverBlack);
            Color.Return(view.ColorOverWhite);
            Color.Return(view.BlurredOverBlack);
            Color.Return(view.BlurredOverWhite);
            Mask.Return(view.Mask);
            Depth.Return(view.Depth);
            Normal.Return(view.Normal);
            Labels.Return(view.Labels);
            if (view.Relit != null)
                foreach (var pair in view.Relit.Values)
                {
                    Color.Return(pair[0]);
                    Color.Return(pair[1]);
                }
        }

        public Action<CapturedView> ReturnCallback => Return;
    }
}
