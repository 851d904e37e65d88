using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>One frame pair of a video: flow from frame <see cref="From"/> to frame <see cref="To"/> (positions in the video).</summary>
    public sealed class FlowPair
    {
        public FlowPair(string video, int from, int to)
        {
            Video = video;
            From = from;
            To = to;
        }

        public string Video { get; }
        public int From { get; }
        public int To { get; }

        /// <summary>Forward: to a later frame; backward: to an earlier one.</summary>
        public bool Forward => To > From;

        public int Span => Forward ? To - From : From - To;

        public string FlowFile => FlowLayout.FlowFile(Video, From, To);
        public string OccludedFile => FlowLayout.OccludedFile(Video, From, To);
        public string OutsideFile => FlowLayout.OutsideFile(Video, From, To);
        public string SceneFlowFile => FlowLayout.SceneFlowFile(Video, From, To);
    }

    /// <summary>The pairs the settings ask for in a video of <c>n</c> frames: per span s, forward (a, a + s) and backward (a, a − s).</summary>
    public static class FlowPairs
    {
        public static IReadOnlyList<FlowPair> Of(string video, int frameCount, FlowSettings settings)
        {
            var pairs = new List<FlowPair>();
            foreach (var span in settings.Spans)
            {
                if (span < 1) continue;
                for (var a = 0; a < frameCount; a++)
                {
                    if (settings.Forward && a + span < frameCount) pairs.Add(new FlowPair(video, a, a + span));
                    if (settings.Backward && a - span >= 0) pairs.Add(new FlowPair(video, a, a - span));
                }
            }
            return pairs;
        }
    }
}
