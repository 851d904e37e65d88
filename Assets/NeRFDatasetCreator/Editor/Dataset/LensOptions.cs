
namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// A lens capture's render: the camera renders Core's wide pinhole (<see cref="LensCapture.WideRender"/>) — its size
    /// and vertical field of view replace the output's — and the data passes render at the supersampled size, so the
    /// depth and normals <see cref="LensResampler"/> takes by nearest sample at silhouettes are at most half a
    /// supersample, not half an output pixel, off each distorted pixel's ray.
    /// </summary>
    public static class LensOptions
    {
        public static void Apply(DatasetSettings settings, CaptureOptions options)
        {
            LensDistortion lens;
            LensPinholeCover wide;
            try
            {
                lens = settings.Lens?.ToDistortion();
                wide = LensCapture.WideRender(lens, settings.Intrinsics());
            }
            catch (InvalidParameterException)
            {
                return; // SettingsValidator has reported it under "lens"; the run is refused before anything renders
            }
            if (wide == null) return;
            options.Width = wide.Width;
            options.Height = wide.Height;
            options.WideVerticalFieldOfViewDegrees = wide.VerticalFovDegrees;
            options.DepthAndNormalAtOutputSize = false;
        }
    }
}
