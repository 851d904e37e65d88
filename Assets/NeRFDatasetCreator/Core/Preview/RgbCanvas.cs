using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// An opaque 8-bit RGB raster, top row first, with the few primitives the rig picture needs: filled rectangles
    /// and discs, one-pixel lines and circles, and 5×7 text. Everything outside the canvas (or its clip rectangle)
    /// is skipped, so callers never clamp. <see cref="Pixels"/> goes straight to <see cref="PngWriter"/> as Rgb8.
    /// </summary>
    public sealed class RgbCanvas
    {
        int _clipLeft, _clipTop, _clipRight, _clipBottom;

        public RgbCanvas(int width, int height, byte[] background)
        {
            if (width < 1 || height < 1) throw new ArgumentOutOfRangeException(nameof(width), "A canvas has at least one pixel.");
            Width = width;
            Height = height;
            Pixels = new byte[width * height * 3];
            ResetClip();
            FillRect(0, 0, width, height, background);
        }

        public int Width { get; }
        public int Height { get; }

        /// <summary>Tightly packed RGB bytes, rows top first.</summary>
        public byte[] Pixels { get; }

        /// <summary>Drawing is limited to [left, right) × [top, bottom) until <see cref="ResetClip"/>.</summary>
        public void Clip(int left, int top, int right, int bottom)
        {
            _clipLeft = Math.Max(0, left);
            _clipTop = Math.Max(0, top);
            _clipRight = Math.Min(Width, right);
            _clipBottom = Math.Min(Height, bottom);
        }

        public void ResetClip() => Clip(0, 0, Width, Height);

        public byte[] Get(int x, int y)
        {
            var i = (y * Width + x) * 3;
            return new[] { Pixels[i], Pixels[i + 1], Pixels[i + 2] };
        }

        /// <summary>
        /// When set, asked for every pixel inside the clip rectangle before it is drawn; false leaves the pixel as it is.
        /// The rig picture paints cameras nearest-last this way without sorting them (<see cref="PaintersBuffer"/>).
        /// </summary>
        public Func<int, int, bool> Filter { get; set; }

        public void Set(int x, int y, byte[] rgb)
        {
            if (x < _clipLeft || y < _clipTop || x >= _clipRight || y >= _clipBottom) return;
            if (Filter != null && !Filter(x, y)) return;
            var i = (y * Width + x) * 3;
            Pixels[i] = rgb[0];
            Pixels[i + 1] = rgb[1];
            Pixels[i + 2] = rgb[2];
        }

        public void FillRect(int left, int top, int width, int height, byte[] rgb)
        {
            for (var y = top; y < top + height; y++)
                for (var x = left; x < left + width; x++)
                    Set(x, y, rgb);
        }

        /// <summary>Every pixel whose centre lies within <paramref name="radius"/> of (cx, cy), in pixel units.</summary>
        public void FillDisc(double cx, double cy, double radius, byte[] rgb)
        {
            var r2 = radius * radius;
            for (var y = (int)Math.Floor(cy - radius); y <= (int)Math.Ceiling(cy + radius); y++)
                for (var x = (int)Math.Floor(cx - radius); x <= (int)Math.Ceiling(cx + radius); x++)
                {
                    var dx = x + 0.5 - cx;
                    var dy = y + 0.5 - cy;
                    if (dx * dx + dy * dy <= r2) Set(x, y, rgb);
                }
        }

        /// <summary>A line one pixel wide from (x0, y0) to (x1, y1), sampled at every pixel step along its longer axis.</summary>
        public void Line(double x0, double y0, double x1, double y1, byte[] rgb)
        {
            var steps = (int)Math.Ceiling(Math.Max(Math.Abs(x1 - x0), Math.Abs(y1 - y0)));
            if (steps > 1 << 16) return; // off-canvas nonsense; nothing sensible to draw
            for (var k = 0; k <= steps; k++)
            {
                var t = steps == 0 ? 0 : (double)k / steps;
                Set((int)Math.Floor(x0 + (x1 - x0) * t), (int)Math.Floor(y0 + (y1 - y0) * t), rgb);
            }
        }

        /// <summary>A circle outline one pixel wide; every <paramref name="dash"/>-th arc pixel is skipped for a dotted look (0 for none).</summary>
        public void Circle(double cx, double cy, double radius, byte[] rgb, int dash = 0)
        {
            var steps = Math.Max(8, (int)Math.Ceiling(2 * Math.PI * radius));
            if (steps > 1 << 16) return;
            for (var k = 0; k < steps; k++)
            {
                if (dash > 0 && k / dash % 2 == 1) continue;
                var a = 2 * Math.PI * k / steps;
                Set((int)Math.Floor(cx + radius * Math.Cos(a)), (int)Math.Floor(cy + radius * Math.Sin(a)), rgb);
            }
        }

        /// <summary>Text in <see cref="PixelFont"/>'s 5×7 glyphs, each font pixel drawn as a <paramref name="scale"/>² block; returns the width drawn.</summary>
        public int Text(int left, int top, string text, byte[] rgb, int scale = 2)
        {
            var x = left;
            foreach (var c in text)
            {
                var rows = PixelFont.Glyph(c);
                for (var row = 0; row < PixelFont.GlyphHeight; row++)
                    for (var col = 0; col < PixelFont.GlyphWidth; col++)
                        if ((rows[row] & (1 << (PixelFont.GlyphWidth - 1 - col))) != 0)
                            FillRect(x + col * scale, top + row * scale, scale, scale, rgb);
                x += PixelFont.Advance * scale;
            }
            return x - left;
        }
    }
}
