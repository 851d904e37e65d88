namespace NerfDatasetCreator
{
    /// <summary>
    /// A JPEG encoder and decoder supplied by the host (<see cref="JpegWriter.Codec"/>): Core ships no JPEG code and no
    /// third-party binary. The <c>nerf-dataset</c> tool and the .NET tests install LibJpeg.NET (BitMiracle, BSD-3, from
    /// NuGet); Unity's Editor installs its own encoder (<c>ImageConversion.EncodeArrayToJPG</c>) when it loads.
    /// </summary>
    public interface IJpegCodec
    {
        /// <summary>What encodes, for the export's notes, e.g. "LibJpeg.NET 1.5.324, 4:4:4".</summary>
        string Name { get; }

        /// <summary>Baseline JPEG of 8-bit RGB, R G B per pixel, top row first, at IJG quality 1–100. Safe on any thread.</summary>
        byte[] Encode(byte[] rgb, int width, int height, int quality);

        /// <summary>8-bit RGB, top row first.</summary>
        byte[] Decode(byte[] jpeg, out int width, out int height);
    }
}
