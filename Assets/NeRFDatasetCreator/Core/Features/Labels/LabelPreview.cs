using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A split's colour-coded preview, <c>labels_preview_&lt;split&gt;.png</c>: a sheet of some of its views' instance
    /// maps, each id in its display colour (<see cref="LabelColours"/>), background black. For looking at, not for
    /// training: loaders read the 16-bit maps and labels.json.
    /// </summary>
    public static class LabelPreview
    {
        /// <summary>The most views a sheet shows (the first ones, in index order).</summary>
        public const int MaxViews = 16;

        /// <summary>The widest a sheet's tile is, in pixels (larger maps are sampled down, nearest id: never blended).</summary>
        public const int MaxTileSize = 256;

        /// <summary>
        /// An RGB8 PNG of <paramref name="maps"/> (instance maps of width × height, top row first) in a grid of up to
        /// four columns; at most <see cref="MaxViews"/> maps are drawn.
        /// </summary>
        public static byte[] Encode(IReadOnlyList<ushort[]> maps, int width, int height)
        {
            if (maps == null) throw new ArgumentNullException(nameof(maps));
            if (maps.Count == 0) throw new ArgumentException("a preview needs at least one map", nameof(maps));
            if (width < 1 || height < 1) throw new ArgumentOutOfRangeException(nameof(width), "a map has at least one pixel");
            int count = Math.Min(maps.Count, MaxViews);
            int step = Math.Max(1, (Math.Max(width, height) + MaxTileSize - 1) / MaxTileSize);
            int tileW = (width + step - 1) / step, tileH = (height + step - 1) / step;
            int columns = Math.Min(4, count), rows = (count + columns - 1) / columns;
            int sheetW = columns * tileW, sheetH = rows * tileH;
            var rgb = new byte[sheetW * sheetH * 3];
            for (var m = 0; m < count; m++)
            {
                var map = maps[m];
                if (map == null || map.Length != width * height)
                    throw new ArgumentException("map " + m.ToString(System.Globalization.CultureInfo.InvariantCulture) + " is not width × height ids", nameof(maps));
                int left = (m % columns) * tileW, top = (m / columns) * tileH;
                for (var y = 0; y < tileH; y++)
                for (var x = 0; x < tileW; x++)
                {
                    // Nearest sample, so every preview pixel is one id's colour.
                    var id = map[Math.Min(height - 1, y * step) * width + Math.Min(width - 1, x * step)];
                    LabelColours.Rgb(id, out var r, out var g, out var b);
                    var o = ((top + y) * sheetW + left + x) * 3;
                    rgb[o] = r;
                    rgb[o + 1] = g;
                    rgb[o + 2] = b;
                }
            }
            return PngWriter.Encode(rgb, sheetW, sheetH, PngPixelFormat.Rgb8);
        }
    }
}
