using System;

namespace NerfDatasetCreator
{
    /// <summary>How a material pass's 8-bit PNG holds its linear values (dataset_config.json <c>materials.encodings</c>).</summary>
    public enum MaterialPngEncoding
    {
        /// <summary>No PNG: the float EXR only (emission, whose values may exceed 1).</summary>
        None,
        /// <summary>round(255 · sRGB(v)), IEC 61966-2-1: colours (base colour, specular colour), as a picture is stored.</summary>
        Srgb,
        /// <summary>round(255 · v), no curve: scalar parameters (metallic, roughness), R = G = B.</summary>
        Linear,
    }

    /// <summary>
    /// One material pass as every part of the feature names it: its settings name, its files, its frame key, its PNG
    /// encoding, whether it is one value per sample (written R = G = B) or a colour, and the <see cref="RawFrame"/> array
    /// it reads. The five are <see cref="MaterialPassFiles.All"/>.
    /// </summary>
    public sealed class MaterialPass
    {
        public MaterialPass(string name, DatasetFileKind exr, DatasetFileKind? png, string key, MaterialPngEncoding encoding, bool grey, Func<RawFrame, float[]> samples)
        {
            Name = name;
            Exr = exr;
            Png = png;
            Key = key;
            Encoding = encoding;
            Grey = grey;
            Samples = samples;
        }

        /// <summary>The settings name (<see cref="MaterialPassNames"/>).</summary>
        public string Name { get; }

        /// <summary>The float32 RGBA EXR, the truth.</summary>
        public DatasetFileKind Exr { get; }

        /// <summary>The 8-bit RGBA PNG, or null (emission).</summary>
        public DatasetFileKind? Png { get; }

        /// <summary>The frame key (<see cref="MaterialKeys"/>): it names the PNG, or the EXR when there is no PNG.</summary>
        public string Key { get; }

        public MaterialPngEncoding Encoding { get; }

        /// <summary>One float per sample in the raw frame (metallic, roughness), written R = G = B; else 4 floats per sample (A ignored).</summary>
        public bool Grey { get; }

        public Func<RawFrame, float[]> Samples { get; }

        public int FloatsPerSample => Grey ? 1 : 4;

        /// <summary>The file the frame key names.</summary>
        public DatasetFileKind KeyFile => Png ?? Exr;

        /// <summary>dataset_config.json's name for the encoding of the pass's PNG (<c>"srgb"</c>, <c>"linear"</c>), or null without one.</summary>
        public string EncodingName => Encoding == MaterialPngEncoding.Srgb ? "srgb" : Encoding == MaterialPngEncoding.Linear ? "linear" : null;
    }
}
