namespace NerfDatasetCreator
{
    /// <summary>
    /// How the mask, depth and normal passes draw one material so that they cover what its colour pass covers:
    /// which faces, and whether and where fragments are clipped. Alpha for clipping is
    /// <c>AlphaTexture.a (sampled at uv0 with the texture's scale and offset) × ColorAlpha</c>, clipped below
    /// <see cref="Cutoff"/> as Unity's <c>clip(alpha − cutoff)</c> does.
    /// </summary>
    public sealed class DataPassSettings
    {
        public DataPassSettings(FaceCulling cull, bool alphaClip, double cutoff, string alphaTexture, double colorAlpha, string warning)
        {
            Cull = cull;
            AlphaClip = alphaClip;
            Cutoff = cutoff;
            AlphaTexture = alphaTexture;
            ColorAlpha = colorAlpha;
            Warning = warning;
        }

        /// <summary>Opaque, front faces only, no clipping: what every data pass drew before materials were read.</summary>
        public static DataPassSettings Opaque(string warning = null) => new DataPassSettings(FaceCulling.Back, false, 0, null, 1, warning);

        public FaceCulling Cull { get; }
        public bool AlphaClip { get; }
        public double Cutoff { get; }

        /// <summary>The source material's texture property whose alpha is clipped (e.g. <c>_MainTex</c>, <c>_BaseMap</c>), or null (alpha 1).</summary>
        public string AlphaTexture { get; }

        /// <summary>The alpha of the material's colour (<c>_Color</c>, <c>_BaseColor</c>) that multiplies the texture's, or 1.</summary>
        public double ColorAlpha { get; }

        /// <summary>Null when the data passes reproduce the material; otherwise what they do not reproduce, for one warning per shader.</summary>
        public string Warning { get; }

        public bool IsExact => Warning == null;

        public override string ToString() => "cull " + Cull + (AlphaClip
            ? ", clip " + (AlphaTexture ?? "1") + ".a × " + ColorAlpha.ToString(System.Globalization.CultureInfo.InvariantCulture) +
              " < " + Cutoff.ToString(System.Globalization.CultureInfo.InvariantCulture)
            : ", no clip") + (Warning == null ? "" : " (" + Warning + ")");
    }
}
