using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The relit colour of a view (<see cref="RawFrame.Relit"/>) made ready for the colour pipeline the view's own colour
    /// goes through (<see cref="ViewFileWriter"/>: difference matting or straight alpha, the linear HDR image): each
    /// condition's render carries only colour; its geometry — the mask pass, the colour-space flag, the size — is the
    /// view's, so the relit image's alpha is the view's.
    /// </summary>
    public static class RelitFrames
    {
        /// <summary>
        /// A frame of <paramref name="relit"/>'s colour arrays with <paramref name="view"/>'s mask and colour-space flag;
        /// refused when the sizes differ or the colour is missing.
        /// </summary>
        public static RawFrame WithViewGeometry(string key, RawFrame relit, RawFrame view)
        {
            if (relit == null)
                throw new InvalidOperationException("This run relights the views, but the frame carries no colour for \"" + key + "\" (RawFrame.Relit[\"" + key + "\"]).");
            if (relit.Width != view.Width || relit.Height != view.Height || relit.Supersampling != view.Supersampling)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("frame.Relit[\"" + key + "\"]", relit.Width + "×" + relit.Height + " at supersampling " + relit.Supersampling,
                        "is not the size of the view's colour render (" + view.Width + "×" + view.Height + " at supersampling " + view.Supersampling + ").",
                        "Render every lighting condition with the view's camera and render texture."),
                });
            if (relit.ColorOverBlack == null && relit.ColorSrgb == null && relit.ColorLinear == null)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem("frame.Relit[\"" + key + "\"]", "no colour", "carries no colour array.",
                        "Read the condition's colour render back into ColorOverBlack/ColorOverWhite (or ColorSrgb/ColorLinear)."),
                });
            return new RawFrame(view.Width, view.Height, view.Supersampling)
            {
                ColorSrgb = relit.ColorSrgb, ColorLinear = relit.ColorLinear,
                ColorOverBlack = relit.ColorOverBlack, ColorOverWhite = relit.ColorOverWhite,
                ColorIsGammaEncoded = view.ColorIsGammaEncoded,
                Mask = view.Mask, MaskBytesPerPixel = view.MaskBytesPerPixel,
            };
        }

        /// <summary>Each relit frame of <paramref name="wide"/> passed through <paramref name="resample"/> (a lens's wide render into the distorted frame); null without any.</summary>
        public static Dictionary<string, RawFrame> Resampled(RawFrame wide, Func<RawFrame, RawFrame> resample)
        {
            if (wide.Relit == null) return null;
            var result = new Dictionary<string, RawFrame>(StringComparer.Ordinal);
            foreach (var pair in wide.Relit) result[pair.Key] = pair.Value == null ? null : resample(pair.Value);
            return result;
        }
    }
}
