using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What the capture knows about how it rendered the material passes, for dataset_config.json's <c>materials</c> record
    /// (<see cref="MaterialRecord"/>): the render pipeline (<see cref="Urp"/>, <see cref="Builtin"/>, or
    /// <see cref="Analytic"/> for Core's analytic scene) and the shaders whose parameters were read exactly and those that
    /// were not (their pixels are 0 in <c>r_&lt;i&gt;_material_coverage.png</c>). Set on <see cref="Provenance.Materials"/>.
    /// </summary>
    public sealed class MaterialCaptureFacts
    {
        public const string Urp = "urp", Builtin = "builtin", Analytic = "analytic";

        public MaterialCaptureFacts(string pipeline, IEnumerable<string> supportedShaders, IEnumerable<string> unsupportedShaders)
        {
            Pipeline = pipeline;
            SupportedShaders = Sorted(supportedShaders);
            UnsupportedShaders = Sorted(unsupportedShaders);
        }

        public string Pipeline { get; }

        /// <summary>Shader names, sorted ordinally and without repeats (the record's bytes do not depend on the scene's order).</summary>
        public IReadOnlyList<string> SupportedShaders { get; }

        public IReadOnlyList<string> UnsupportedShaders { get; }

        static List<string> Sorted(IEnumerable<string> names)
        {
            var set = new SortedSet<string>(System.StringComparer.Ordinal);
            if (names != null)
                foreach (var name in names)
                    if (!string.IsNullOrEmpty(name)) set.Add(name);
            return new List<string>(set);
        }
    }
}
