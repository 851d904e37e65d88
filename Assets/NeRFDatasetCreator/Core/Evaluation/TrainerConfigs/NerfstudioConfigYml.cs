using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// nerfstudio's <c>config.yml</c>: <c>ExperimentConfig.save_config</c> writes <c>yaml.dump(self)</c> of the whole
    /// TrainerConfig (nerfstudio 50e0e3c nerfstudio/configs/experiment_config.py lines 130–137), keys sorted, one per
    /// line, nested by indentation: <c>method_name: splatfacto</c> at the top, the model's <c>background_color: random</c>
    /// (splatfacto.py line 95: random | black | white; nerfacto.py line 60 adds last_sample) under
    /// <c>pipeline.model</c>, the blender-data dataparser's <c>alpha_color: white</c> (blender_dataparser.py line 44)
    /// under <c>pipeline.datamanager.dataparser</c>. Only those scalar lines are read (a tensor colour is reported as such).
    /// </summary>
    public static class NerfstudioConfigYml
    {
        public const string FileName = "config.yml";

        public sealed class Facts
        {
            public string MethodName;

            /// <summary>The model's background_color as written (null when absent; "(a colour tensor)" for a tensor).</summary>
            public string BackgroundColor;

            /// <summary>The dataparser's alpha_color as written ("null" when none; absent for dataparsers without the key).</summary>
            public string AlphaColor;
        }

        public static Facts Read(string text)
        {
            var facts = new Facts();
            foreach (var raw in (text ?? "").Split('\n'))
            {
                var line = raw.TrimEnd('\r');
                var trimmed = line.TrimStart();
                if (trimmed.StartsWith("method_name:", StringComparison.Ordinal) && line.Length == trimmed.Length) facts.MethodName = Value(trimmed);
                else if (trimmed.StartsWith("background_color:", StringComparison.Ordinal)) facts.BackgroundColor = Value(trimmed);
                else if (trimmed.StartsWith("alpha_color:", StringComparison.Ordinal)) facts.AlphaColor = Value(trimmed);
            }
            return facts;
        }

        static string Value(string line)
        {
            var v = line.Substring(line.IndexOf(':') + 1).Trim();
            if (v.StartsWith("!!", StringComparison.Ordinal) || v.Length == 0) return "(a colour tensor)";
            return v.Trim('\'', '"');
        }

        /// <summary>
        /// The background the model's renders and ns-eval use for this config: the model's background_color, where
        /// random means splatfacto's evaluation colour and nerfacto's black (splatfacto.py lines 247–250 and 454–465;
        /// renderers.py blend_background lines 169–171); null when unknown.
        /// </summary>
        public static string RenderBackground(Facts f)
        {
            switch (f.BackgroundColor)
            {
                case "white": return EvalProtocol.White;
                case "black": return EvalProtocol.Black;
                case "random": return EvalProtocol.Random;
                default: return null;
            }
        }
    }
}
