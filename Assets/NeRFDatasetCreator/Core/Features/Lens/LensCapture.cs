namespace NerfDatasetCreator
{
    /// <summary>
    /// What a capture through a lens renders: the centred wide pinhole (<see cref="LensPinholeCover.Centred"/>) of the
    /// output frame, at the density the frame needs. The Unity camera renders it from
    /// <see cref="LensPinholeCover.VerticalFovDegrees"/> and the size <see cref="LensPinholeCover.Width"/> ×
    /// <see cref="LensPinholeCover.Height"/> (times the supersampling), and <see cref="LensResampler"/> turns it into the
    /// distorted frame.
    /// </summary>
    public static class LensCapture
    {
        /// <summary>The wide render for <paramref name="lens"/> on the output frame <paramref name="output"/>; null without a lens.</summary>
        public static LensPinholeCover WideRender(LensDistortion lens, CameraIntrinsics output) =>
            lens == null ? null : LensPinholeCover.For(lens, output).Centred();

        /// <summary>The resampler of a plan (its settings' lens on its intrinsics), or null when the plan has no lens.</summary>
        public static LensResampler ResamplerFor(CapturePlan plan)
        {
            var lens = plan.Settings.Lens?.ToDistortion();
            return lens == null ? null : new LensResampler(lens, plan.Intrinsics, WideRender(lens, plan.Intrinsics));
        }
    }
}
