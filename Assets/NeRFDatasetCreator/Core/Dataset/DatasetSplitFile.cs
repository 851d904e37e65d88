using System.Collections.Generic;
using Newtonsoft.Json;
using Newtonsoft.Json.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A transforms file as <see cref="DatasetFolder"/> read it, tolerant of mistakes: what could not be read is null and,
    /// in <see cref="DatasetReadMode.Strict"/> mode, listed in <see cref="Problems"/>.
    /// </summary>
    public sealed class DatasetSplitFile
    {
        /// <summary>The file's name (<c>transforms_train.json</c>, or the name it was read under).</summary>
        public string FileName { get; internal set; }

        /// <summary><c>train</c>, <c>val</c> or <c>test</c>; null for a file of another name (an imported transforms.json).</summary>
        public string Split { get; internal set; }

        /// <summary>The dataset folder (absolute) its frames' files resolve against; null when read from text alone.</summary>
        public string Root { get; internal set; }

        public DatasetReadMode Mode { get; internal set; }

        public double? CameraAngleX { get; internal set; }
        public double? CameraAngleY { get; internal set; }
        public int? W { get; internal set; }
        public int? H { get; internal set; }
        public double? IntegerDepthScale { get; internal set; }
        public double? DepthUnitScaleFactor { get; internal set; }

        /// <summary>The file's camera keys (<c>fl_x</c>, <c>cx</c>, <c>w</c>, <c>camera_angle_x</c>, …), each null when absent or not a number.</summary>
        public FrameIntrinsics Intrinsics { get; internal set; } = FrameIntrinsics.None;

        /// <summary>The file's one lens (<see cref="TransformsLens.OfFile"/>), null for a pinhole or when <see cref="LensProblems"/> says why not.</summary>
        public LensDistortion Lens { get; internal set; }
        public List<ValidationProblem> LensProblems { get; } = new List<ValidationProblem>();

        /// <summary>The frames, in order (empty when they were streamed to a callback instead).</summary>
        public List<DatasetFrame> Frames { get; } = new List<DatasetFrame>();

        /// <summary>How many entries <c>frames</c> has (also when they were streamed rather than kept in <see cref="Frames"/>).</summary>
        public int FrameCount { get; internal set; }

        /// <summary>Whether <c>frames</c> is there and a list; <see cref="FramesShown"/> says what it is otherwise.</summary>
        public bool HasFrameList { get; internal set; }

        /// <summary>What <c>frames</c> is when it is not a list: "missing", or its JSON type (Object, String, …).</summary>
        public string FramesShown { get; internal set; } = "missing";

        /// <summary><c>frames</c> as compact JSON text when it is not a list ("missing" when absent), for messages.</summary>
        public string FramesText { get; internal set; } = "missing";

        /// <summary>Whether the file is a JSON object at all; <see cref="TypeShown"/> says what it is otherwise.</summary>
        public bool IsObject { get; internal set; } = true;

        /// <summary>The JSON type of the file's value (Object, Array, …).</summary>
        public string TypeShown { get; internal set; } = "Object";

        /// <summary>How many top-level keys come before <c>frames</c>: merge writes the merged frames back in the same place.</summary>
        internal int FramesAt { get; set; } = -1;

        /// <summary>Problems with the document's structure (Strict mode), e.g. "camera_angle_x is missing.".</summary>
        public List<string> Problems { get; } = new List<string>();

        /// <summary>Every top-level key but <c>frames</c>, as written (strings kept as strings): merge copies them verbatim.</summary>
        internal JObject Top { get; set; } = new JObject();

        /// <summary>A top-level value as written, or null: for keys the readers carry as they are (scene_normalisation, aabb_scale).</summary>
        public JToken Value(string key) => Top[key];

        /// <summary>A top-level value as compact JSON text, or null when absent: for messages that quote what the file holds.</summary>
        public string Text(string key) => Top[key]?.ToString(Formatting.None);

        /// <summary>The strings of a top-level list (nerfstudio's <c>train_filenames</c>, …), skipping other values; empty when absent.</summary>
        public IReadOnlyList<string> Strings(string key)
        {
            var list = new List<string>();
            if (Top[key] is JArray array)
                foreach (var item in array)
                    if (item.Type == JTokenType.String) list.Add((string)item);
            return list;
        }

        /// <summary>Whether a top-level key is the JSON value <c>true</c>.</summary>
        public bool IsTrue(string key) => Top[key] is JValue v && v.Type == JTokenType.Boolean && (bool)v;

        /// <summary>Whether the file has a top-level key.</summary>
        public bool Has(string key) => Top[key] != null;
    }
}
