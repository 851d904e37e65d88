using UnityEngine;

namespace NerfDatasetCreator.Editor.Tests
{
    /// <summary>Where a decoded image's alpha sits: the alpha-weighted mean of pixel centres, in pixels from the bottom left.</summary>
    static class AlphaCentroid
    {
        /// <summary>The centroid and the alpha sum (0 for an empty image, whose centroid is then NaN).</summary>
        public static Vector2 Of(Texture2D texture, out double alphaSum)
        {
            double sx = 0, sy = 0, sa = 0;
            var pixels = texture.GetPixels32();
            for (var py = 0; py < texture.height; py++)
                for (var px = 0; px < texture.width; px++)
                {
                    var a = pixels[py * texture.width + px].a / 255.0;
                    sx += a * (px + 0.5);
                    sy += a * (py + 0.5);
                    sa += a;
                }
            alphaSum = sa;
            return new Vector2((float)(sx / sa), (float)(sy / sa));
        }
    }
}
