using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// 3DGS's <c>&lt;model&gt;/cfg_args</c>: train.py's <c>prepare_output_and_logger</c> writes
    /// <c>str(Namespace(**vars(args)))</c> of the ModelParams group (graphdeco-inria/gaussian-splatting 82bc469
    /// train.py, the <c>cfg_log_f.write</c> line; arguments/__init__.py <c>ModelParams</c>: <c>_white_background = False</c>,
    /// flag <c>-w</c>), e.g. <c>Namespace(data_device='cuda', eval=True, images='images', model_path='output/x',
    /// resolution=-1, sh_degree=3, source_path='/data/lego', white_background=True)</c>. Read as Python's repr:
    /// <c>key=value</c> pairs at the top level, quoted strings skipped whole so a path holding "white_background=" is
    /// never taken for the key. <c>random_background</c> is an OptimizationParams flag and is not written there.
    /// </summary>
    public static class GaussianCfgArgs
    {
        public const string FileName = "cfg_args";

        /// <summary>The top-level <c>key=value</c> pairs of a Namespace repr, values as written (strings with their quotes); null when it is not one.</summary>
        public static Dictionary<string, string> Parse(string text)
        {
            var t = (text ?? "").Trim();
            if (!t.StartsWith("Namespace(", StringComparison.Ordinal) || !t.EndsWith(")", StringComparison.Ordinal)) return null;
            var body = t.Substring("Namespace(".Length, t.Length - "Namespace(".Length - 1);
            var pairs = new Dictionary<string, string>(StringComparer.Ordinal);
            var depth = 0;
            var start = 0;
            for (var i = 0; i <= body.Length; i++)
            {
                if (i < body.Length)
                {
                    var c = body[i];
                    if (c == '\'' || c == '"')
                    {
                        // A Python string literal: skip to its closing quote (backslash escapes the next character).
                        for (i++; i < body.Length && body[i] != c; i++)
                            if (body[i] == '\\') i++;
                        continue;
                    }
                    if (c == '(' || c == '[' || c == '{') { depth++; continue; }
                    if (c == ')' || c == ']' || c == '}') { depth--; continue; }
                    if (c != ',' || depth != 0) continue;
                }
                var item = body.Substring(start, Math.Min(i, body.Length) - start).Trim();
                start = i + 1;
                var eq = item.IndexOf('=');
                if (eq > 0) pairs[item.Substring(0, eq).Trim()] = item.Substring(eq + 1).Trim();
            }
            return pairs;
        }

        /// <summary>The background the model was trained and renders over: white with <c>white_background=True</c>, black with False; null when the key is absent.</summary>
        public static string Background(Dictionary<string, string> pairs)
        {
            if (pairs == null || !pairs.TryGetValue("white_background", out var value)) return null;
            return value == "True" ? EvalProtocol.White : value == "False" ? EvalProtocol.Black : null;
        }
    }
}
