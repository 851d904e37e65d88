using System;
using System.Collections.Generic;
using System.Linq;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What a capture's material passes could read (issue 38): the pipeline that drew them and every shader seen, those
    /// read exactly and the others by name with the reason (their samples are 0 in <c>r_&lt;i&gt;_material_coverage.png</c>).
    /// Filled by the Unity Editor (<c>MaterialPassCapture</c>), carried as <see cref="Provenance.Materials"/> (<see cref="ToFacts"/>) into
    /// <c>dataset_config.json</c>'s <c>materials</c> record ("pipeline", "supported_shaders", "unsupported_shaders").
    /// </summary>
    public sealed class MaterialShaderReport
    {
        public MaterialShaderReport(MaterialPipeline pipeline, IEnumerable<string> supported, IEnumerable<KeyValuePair<string, string>> unsupported)
        {
            Pipeline = pipeline;
            Supported = (supported ?? Enumerable.Empty<string>()).OrderBy(s => s, StringComparer.Ordinal).ToList();
            Unsupported = (unsupported ?? Enumerable.Empty<KeyValuePair<string, string>>())
                .OrderBy(p => p.Key, StringComparer.Ordinal).ToList();
        }

        public MaterialPipeline Pipeline { get; }

        /// <summary>"urp" or "builtin", as the contract names them.</summary>
        public string PipelineName => Pipeline == MaterialPipeline.Urp ? "urp" : "builtin";

        public IReadOnlyList<string> Supported { get; }

        /// <summary>Shader name → why its parameters are not read.</summary>
        public IReadOnlyList<KeyValuePair<string, string>> Unsupported { get; }

        public JObject ToJson() => new JObject
        {
            ["pipeline"] = PipelineName,
            ["supported_shaders"] = new JArray(Supported),
            ["unsupported_shaders"] = new JArray(Unsupported.Select(p => p.Key)),
            ["unsupported_reasons"] = new JObject(Unsupported.Select(p => new JProperty(p.Key, p.Value))),
        };

        /// <summary>The record's facts (<see cref="Provenance.Materials"/>, written by <see cref="MaterialRecord"/>); the reasons stay in the Console line.</summary>
        public MaterialCaptureFacts ToFacts() => new MaterialCaptureFacts(PipelineName, Supported, Unsupported.Select(p => p.Key));

        /// <summary>One line for the Console: null when every shader was read exactly.</summary>
        public string Warning() => Unsupported.Count == 0 ? null
            : "material passes: " + Unsupported.Count + " shader(s) are not read and their pixels are 0 in r_<i>_material_coverage.png: " +
              string.Join("; ", Unsupported.Select(p => p.Key + " (" + p.Value + ")")) + ".";
    }
}
