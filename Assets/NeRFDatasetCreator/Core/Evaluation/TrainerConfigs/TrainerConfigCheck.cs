using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>check &lt;dataset&gt; --model &lt;dir&gt;</c>: compares the dataset's protocol (<see cref="EvalProtocolFile"/>,
    /// or the derived default) with what a trainer wrote down about its run — 3DGS <c>cfg_args</c>
    /// (<see cref="GaussianCfgArgs"/>), nerfstudio <c>config.yml</c> (<see cref="NerfstudioConfigYml"/>) — the one
    /// mismatch users cannot see until the numbers are wrong.
    /// </summary>
    public static class TrainerConfigCheck
    {
        public sealed class Result
        {
            /// <summary>What was read, one line each.</summary>
            public List<string> Read = new List<string>();

            /// <summary>Each disagreement with the protocol, with the fix.</summary>
            public List<string> Warnings = new List<string>();
        }

        /// <summary>
        /// The comparison for the trained output <paramref name="model"/> (a folder holding cfg_args or config.yml, or one
        /// of those files). Throws <see cref="InvalidParameterException"/> naming <c>--model</c> when it holds neither.
        /// </summary>
        public static Result Run(string datasetRoot, string model)
        {
            var protocol = EvalProtocolFile.Read(datasetRoot) ?? EvalProtocolFile.Derived(datasetRoot);
            var hasFile = File.Exists(Path.Combine(datasetRoot, EvalProtocolFile.FileName));
            var cfg = File.Exists(model) ? (Path.GetFileName(model) == GaussianCfgArgs.FileName ? model : null) : Path.Combine(model ?? "", GaussianCfgArgs.FileName);
            var yml = File.Exists(model) ? (Path.GetFileName(model) == NerfstudioConfigYml.FileName ? model : null) : Path.Combine(model ?? "", NerfstudioConfigYml.FileName);
            var result = new Result();
            var source = hasFile ? EvalProtocolFile.FileName : "the default protocol (the dataset has no " + EvalProtocolFile.FileName + ")";
            var found = false;
            if (cfg != null && File.Exists(cfg))
            {
                found = true;
                var pairs = GaussianCfgArgs.Parse(FileOps.ReadText(cfg));
                var trained = GaussianCfgArgs.Background(pairs);
                if (pairs == null) result.Warnings.Add(cfg + " is not a Python Namespace(...) repr as 3DGS train.py writes it; not compared.");
                else if (trained == null) result.Warnings.Add(cfg + " has no white_background=True/False; not compared.");
                else
                {
                    result.Read.Add("3DGS " + cfg + ": white_background=" + pairs["white_background"] + " (trained and rendered over " + trained + ")" +
                                    (pairs.TryGetValue("resolution", out var r) ? ", resolution=" + r : ""));
                    var wanted = protocol.Background == EvalProtocol.Random ? EvalProtocol.White : protocol.Background;
                    if (wanted != EvalProtocol.Dataset && wanted != trained)
                        result.Warnings.Add("3DGS " + cfg + " says white_background=" + pairs["white_background"] + " (" + trained + ") but " + source + " says " + protocol.Describe() +
                                            ": evaluate will refuse its renders over " + wanted + ". Train again " + (wanted == EvalProtocol.White ? "with -w" : "without -w") +
                                            ", or score these renders with evaluate --background " + trained + " --override-protocol.");
                    if (pairs.TryGetValue("resolution", out var res) && res != "-1" && res != "1")
                        result.Warnings.Add("3DGS " + cfg + " says resolution=" + res + ": it trained at a reduced resolution, but the protocol's resolution factor is " + protocol.ResolutionFactor + "; render with -r 1 for evaluate.");
                }
            }
            if (yml != null && File.Exists(yml))
            {
                found = true;
                var facts = NerfstudioConfigYml.Read(FileOps.ReadText(yml));
                var renders = NerfstudioConfigYml.RenderBackground(facts);
                result.Read.Add("nerfstudio " + yml + ": method " + (facts.MethodName ?? "?") + ", background_color " + (facts.BackgroundColor ?? "(absent)") +
                                (facts.AlphaColor != null ? ", alpha_color " + facts.AlphaColor : ""));
                if (protocol.Background != EvalProtocol.Dataset)
                {
                    if (renders == null)
                        result.Warnings.Add("nerfstudio " + yml + " says background_color " + (facts.BackgroundColor ?? "(absent)") + ", which is not the protocol's " + protocol.Background +
                                            " (" + source + "): pass --pipeline.model.background-color " + protocol.EvaluationBackgroundName + " to ns-train.");
                    else if (renders != protocol.Background)
                        result.Warnings.Add("nerfstudio " + yml + " says background_color " + facts.BackgroundColor + " but " + source + " says " + protocol.Describe() +
                                            (renders == EvalProtocol.Random ? ": ns-eval and ns-render then use splatfacto's (0.149, 0.165, 0.216) or nerfacto's black, not " + protocol.EvaluationBackgroundName : "") +
                                            ". Train with --pipeline.model.background-color " + protocol.EvaluationBackgroundName + ".");
                    if (facts.AlphaColor != null && facts.AlphaColor != "null" && facts.AlphaColor != protocol.EvaluationBackgroundName)
                        result.Warnings.Add("nerfstudio " + yml + " says alpha_color " + facts.AlphaColor + ": the dataparser composited the ground truth over " + facts.AlphaColor + ", not the protocol's " +
                                            protocol.EvaluationBackgroundName + ". Pass --alpha-color " + protocol.EvaluationBackgroundName + " to the blender-data dataparser.");
                }
            }
            if (!found)
                throw new InvalidParameterException(new[] { new ValidationProblem("--model", model ?? "", "holds neither cfg_args (3DGS train.py's) nor config.yml (nerfstudio ns-train's).",
                    "Pass the trained output folder: 3DGS's -m <model> folder, or nerfstudio's outputs/<name>/<method>/<timestamp> folder.") });
            return result;
        }
    }
}
