using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// What the window's Lens section (step 5, Outputs; Documentation~/lens-distortion.md) shows for a
    /// <see cref="LensSettings"/>: the model popup, which coefficient fields to draw, and what choosing another model
    /// does to the coefficients. Engine-free so that it is tested; the section only draws it.
    /// </summary>
    public static class LensChoices
    {
        /// <summary>The popup's config names, in its order.</summary>
        public static readonly string[] ModelNames =
            { LensSettings.ModelNames.None, LensSettings.ModelNames.OpenCv, LensSettings.ModelNames.Fisheye };

        /// <summary>The popup's labels, in <see cref="ModelNames"/> order.</summary>
        public static readonly string[] ModelLabels =
        {
            "None (pinhole)",
            "OpenCV (k1, k2, p1, p2, optional k3)",
            "OpenCV fisheye (k1 … k4)",
        };

        /// <summary>Every coefficient, in the order the config file writes them (LensSettingsJson) and the section draws them.</summary>
        public static readonly string[] AllCoefficients = { "k1", "k2", "p1", "p2", "k3", "k4" };

        static readonly string[] OpenCvCoefficients = { "k1", "k2", "p1", "p2", "k3" };
        static readonly string[] FisheyeCoefficients = { "k1", "k2", "k3", "k4" };

        /// <summary>The popup index of a model name (case and spaces ignored, as the settings read it), or −1 for an unknown one.</summary>
        public static int IndexOf(string model)
        {
            var n = (model ?? LensSettings.ModelNames.None).Trim().ToLowerInvariant();
            return Array.IndexOf(ModelNames, n);
        }

        public static string ModelAt(int index) => ModelNames[index];

        /// <summary>The coefficients <paramref name="model"/> has; none for a pinhole or an unknown model.</summary>
        public static IReadOnlyList<string> Coefficients(string model)
        {
            switch (IndexOf(model))
            {
                case 1: return OpenCvCoefficients;
                case 2: return FisheyeCoefficients;
                default: return Array.Empty<string>();
            }
        }

        /// <summary>
        /// The coefficient fields to draw: the model's own, and any other that is not 0 (a config may give one), so that
        /// the validator's "is not a coefficient of …" appears under a field where it can be set to 0. None for a
        /// pinhole, even one a config gives coefficients: the settings file and the window's undo step hold no lens
        /// without a model (DatasetSettingsJson writes "lens" only with one), so an edit there would be lost; the
        /// validator's error under the model says to pick one, and choosing None again clears them (<see cref="ChangeModel"/>).
        /// </summary>
        public static IReadOnlyList<string> Shown(LensSettings lens)
        {
            if (lens == null) throw new ArgumentNullException(nameof(lens));
            if (!lens.Enabled) return Array.Empty<string>();
            var own = Coefficients(lens.Model);
            var shown = new List<string>();
            foreach (var key in AllCoefficients)
                if (Array.IndexOf((string[])own, key) >= 0 || Get(lens, key) != 0)
                    shown.Add(key);
            return shown;
        }

        /// <summary>
        /// Sets the model, keeping the coefficients the new model also has and clearing the others (the validator refuses
        /// a coefficient the model does not have, and a pinhole with any). Undo brings the old values back.
        /// </summary>
        public static void ChangeModel(LensSettings lens, string model)
        {
            if (lens == null) throw new ArgumentNullException(nameof(lens));
            if (IndexOf(model) < 0) throw new ArgumentException("\"" + model + "\" is not a lens model.", nameof(model));
            lens.Model = model;
            var own = Coefficients(model);
            foreach (var key in AllCoefficients)
                if (Array.IndexOf((string[])own, key) < 0)
                    Set(lens, key, 0);
        }

        public static double Get(LensSettings lens, string key)
        {
            switch (key)
            {
                case "k1": return lens.K1;
                case "k2": return lens.K2;
                case "k3": return lens.K3;
                case "k4": return lens.K4;
                case "p1": return lens.P1;
                case "p2": return lens.P2;
                default: throw new ArgumentOutOfRangeException(nameof(key), key, "not a lens coefficient");
            }
        }

        public static void Set(LensSettings lens, string key, double value)
        {
            switch (key)
            {
                case "k1": lens.K1 = value; break;
                case "k2": lens.K2 = value; break;
                case "k3": lens.K3 = value; break;
                case "k4": lens.K4 = value; break;
                case "p1": lens.P1 = value; break;
                case "p2": lens.P2 = value; break;
                default: throw new ArgumentOutOfRangeException(nameof(key), key, "not a lens coefficient");
            }
        }

        /// <summary>"lens.k1" and the like: the field the validator reports a coefficient under.</summary>
        public static string Field(string key) => LensSettings.Key + "." + key;

        /// <summary>A coefficient field's tooltip: its term in the model's formula (Documentation~/lens-distortion.md), or why it is shown at all.</summary>
        public static string Tooltip(string model, string key)
        {
            if (Array.IndexOf((string[])Coefficients(model), key) < 0)
                return "Not a coefficient of this model (a config file gave it): set it to 0.";
            if (IndexOf(model) == 2)
                return "Fisheye: θ_d = θ(1 + k1 θ² + k2 θ⁴ + k3 θ⁶ + k4 θ⁸), θ = atan r.";
            return key[0] == 'p'
                ? "Tangential term, on OpenCV's normalised coordinates with y pointing down."
                : "Radial term: x_d = x·(1 + k1 r² + k2 r⁴ + k3 r⁶) + tangential. Negative k1 is barrel distortion, positive pincushion.";
        }
    }
}
