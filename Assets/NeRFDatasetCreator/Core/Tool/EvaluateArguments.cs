using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary><c>evaluate &lt;dataset&gt; --renders &lt;dir&gt; [options]</c> → <see cref="ToolInvocation.Evaluation"/>.</summary>
    static class EvaluateArguments
    {
        public static void Parse(ToolInvocation result, Dictionary<string, string> options, List<string> positionals)
        {
            ToolCommandLine.RefuseUnknownOptions(result, options, "renders", "split", "out", "layout", "background", "render-depth", "geometry", "gt-mesh", "threshold", "step");
            var e = new EvaluationOptions();
            if (positionals.Count != 1) result.Errors.Add("evaluate needs exactly one dataset folder, e.g. evaluate NeRFDatasets/lego --renders output/lego.");
            else result.DatasetFolder = e.DatasetFolder = positionals[0];
            if (!options.TryGetValue("renders", out var renders) || string.IsNullOrWhiteSpace(renders))
                result.Errors.Add("evaluate needs --renders <folder>: the trainer's renders of the split (3DGS model folder, ns-render dataset's --output-path, instant-ngp --screenshot_dir, or r_<i>.png files).");
            e.RendersFolder = renders;
            if (options.TryGetValue("split", out var split))
            {
                if (!DatasetSplits.TryParse(split, out _) || split != split.ToLowerInvariant()) result.Errors.Add("--split = " + split + ": is not train, val or test.");
                else e.Split = split;
            }
            if (options.TryGetValue("out", out var output))
            {
                if (string.IsNullOrWhiteSpace(output)) result.Errors.Add("--out is empty; leave it out to write into <renders>/evaluation-<split>.");
                else e.OutFolder = output;
            }
            if (options.TryGetValue("layout", out var layout))
            {
                if (RenderLayouts.TryParse(layout, out var parsed)) e.Layout = parsed;
                else result.Errors.Add("--layout = " + layout + ": is not " + string.Join(", ", RenderLayouts.Names) + ".");
            }
            if (options.TryGetValue("background", out var background))
            {
                if (System.Array.IndexOf(EvaluationBackground.Names, background) < 0) result.Errors.Add("--background = " + background + ": is not white, black or dataset.");
                else e.Background = background;
            }
            if (options.TryGetValue("render-depth", out var depth))
            {
                if (depth == "ray") e.DepthAlongRay = true;
                else if (depth != "z") result.Errors.Add("--render-depth = " + depth + ": is not z (z-depth, splatfacto) or ray (distance along the ray, nerfacto).");
            }
            if (options.TryGetValue("geometry", out var geometry)) e.GeometryPath = geometry;
            if (options.TryGetValue("gt-mesh", out var mesh))
            {
                e.TruthMeshPath = mesh;
                if (geometry == null) result.Errors.Add("--gt-mesh is the ground truth for --geometry; give --geometry <reconstruction> too.");
            }
            if (options.TryGetValue("threshold", out var threshold))
            {
                if (!double.TryParse(threshold, NumberStyles.Float, CultureInfo.InvariantCulture, out var t) || !(t > 0) || double.IsInfinity(t))
                    result.Errors.Add("--threshold = " + threshold + ": must be a distance > 0 in output units, e.g. 0.01.");
                else e.Threshold = t;
                if (geometry == null) result.Errors.Add("--threshold is the F-score threshold of --geometry; give --geometry <reconstruction> too.");
            }
            if (options.TryGetValue("step", out var step))
            {
                if (!int.TryParse(step, NumberStyles.None, CultureInfo.InvariantCulture, out var k))
                    result.Errors.Add("--step = " + step + ": must be a time step number ≥ 0 (the train views' time_step), e.g. --step 0.");
                else e.Step = k;
                if (geometry == null) result.Errors.Add("--step picks the time step of --geometry; give --geometry <reconstruction> too.");
            }
            result.Evaluation = e;
        }
    }
}
