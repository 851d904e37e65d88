using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// dotnet only (not under Assets/): installs the tool's JPEG codec (LibJpeg.NET from NuGet) before any Core test runs,
    /// as the tool's Program does. In Unity the Editor installs its own on load, so the same tests run there unchanged.
    /// </summary>
    [SetUpFixture]
    public sealed class JpegCodecSetup
    {
        [OneTimeSetUp]
        public void Install()
        {
            if (JpegWriter.Codec == null) JpegWriter.Codec = new NerfDatasetCreator.Tool.LibJpegCodec();
        }
    }
}
