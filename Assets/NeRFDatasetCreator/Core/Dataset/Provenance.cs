using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>What a run knows about itself beyond the plan, for <c>dataset_config.json</c>.</summary>
    public sealed class Provenance
    {
        public Provenance(DateTime createdUtc, string unityVersion = null, string tool = null, bool imagesRendered = true)
        {
            ImagesRendered = imagesRendered;
            CreatedUtc = createdUtc.Kind == DateTimeKind.Utc ? createdUtc : createdUtc.ToUniversalTime();
            UnityVersion = unityVersion;
            Tool = tool;
        }

        public DateTime CreatedUtc { get; }

        /// <summary>Unity's <c>Application.unityVersion</c>, or null when the dataset was planned outside Unity.</summary>
        public string UnityVersion { get; }

        /// <summary>What produced the files, e.g. "unity-editor", "unity-batch" or "nerf-dataset plan".</summary>
        public string Tool { get; }

        /// <summary>False for a plan written without images (<c>nerf-dataset plan</c>): validation then skips the image checks.</summary>
        public bool ImagesRendered { get; }

        /// <summary>The Editor's facts about the target and project for <c>unity_frame</c>, or null outside Unity (set by the capture).</summary>
        public UnityFrameFacts UnityFrame { get; set; }

        /// <summary>Issue 38: the shaders the material passes read exactly and the others (null without material passes).</summary>
        public MaterialShaderReport Materials { get; set; }

        /// <summary>Measured figures (e.g. "viewsPerSecond"), written in name order.</summary>
        public SortedDictionary<string, double> Statistics { get; } = new SortedDictionary<string, double>(StringComparer.Ordinal);
    }
}
