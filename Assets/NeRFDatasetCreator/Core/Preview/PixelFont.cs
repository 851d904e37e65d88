using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A 5×7 bitmap font (the classic dot-matrix character-LCD shapes) for the labels of the rig picture: A–Z, 0–9
    /// and a few signs, so Core writes readable pictures without a font file or engine. Lower case is drawn as upper
    /// case; any other character as a blank.
    /// </summary>
    public static class PixelFont
    {
        public const int GlyphWidth = 5;
        public const int GlyphHeight = 7;

        /// <summary>Glyph width plus one blank column.</summary>
        public const int Advance = 6;

        static readonly Dictionary<char, string> Shapes = new Dictionary<char, string>
        {
            ['A'] = "01110 10001 10001 11111 10001 10001 10001",
            ['B'] = "11110 10001 10001 11110 10001 10001 11110",
            ['C'] = "01110 10001 10000 10000 10000 10001 01110",
            ['D'] = "11110 10001 10001 10001 10001 10001 11110",
            ['E'] = "11111 10000 10000 11110 10000 10000 11111",
            ['F'] = "11111 10000 10000 11110 10000 10000 10000",
            ['G'] = "01110 10001 10000 10111 10001 10001 01111",
            ['H'] = "10001 10001 10001 11111 10001 10001 10001",
            ['I'] = "01110 00100 00100 00100 00100 00100 01110",
            ['J'] = "00111 00010 00010 00010 00010 10010 01100",
            ['K'] = "10001 10010 10100 11000 10100 10010 10001",
            ['L'] = "10000 10000 10000 10000 10000 10000 11111",
            ['M'] = "10001 11011 10101 10101 10001 10001 10001",
            ['N'] = "10001 10001 11001 10101 10011 10001 10001",
            ['O'] = "01110 10001 10001 10001 10001 10001 01110",
            ['P'] = "11110 10001 10001 11110 10000 10000 10000",
            ['Q'] = "01110 10001 10001 10001 10101 10010 01101",
            ['R'] = "11110 10001 10001 11110 10100 10010 10001",
            ['S'] = "01111 10000 10000 01110 00001 00001 11110",
            ['T'] = "11111 00100 00100 00100 00100 00100 00100",
            ['U'] = "10001 10001 10001 10001 10001 10001 01110",
            ['V'] = "10001 10001 10001 10001 10001 01010 00100",
            ['W'] = "10001 10001 10001 10101 10101 10101 01010",
            ['X'] = "10001 10001 01010 00100 01010 10001 10001",
            ['Y'] = "10001 10001 10001 01010 00100 00100 00100",
            ['Z'] = "11111 00001 00010 00100 01000 10000 11111",
            ['0'] = "01110 10001 10011 10101 11001 10001 01110",
            ['1'] = "00100 01100 00100 00100 00100 00100 01110",
            ['2'] = "01110 10001 00001 00010 00100 01000 11111",
            ['3'] = "11111 00010 00100 00010 00001 10001 01110",
            ['4'] = "00010 00110 01010 10010 11111 00010 00010",
            ['5'] = "11111 10000 11110 00001 00001 10001 01110",
            ['6'] = "00110 01000 10000 11110 10001 10001 01110",
            ['7'] = "11111 00001 00010 00100 01000 01000 01000",
            ['8'] = "01110 10001 10001 01110 10001 10001 01110",
            ['9'] = "01110 10001 10001 01111 00001 00010 01100",
            [':'] = "00000 01100 01100 00000 01100 01100 00000",
            [','] = "00000 00000 00000 00000 01100 00100 01000",
            ['.'] = "00000 00000 00000 00000 00000 01100 01100",
            ['-'] = "00000 00000 00000 11111 00000 00000 00000",
            ['+'] = "00000 00100 00100 11111 00100 00100 00000",
            ['('] = "00010 00100 01000 01000 01000 00100 00010",
            [')'] = "01000 00100 00010 00010 00010 00100 01000",
            ['/'] = "00001 00001 00010 00100 01000 10000 10000",
            ['='] = "00000 00000 11111 00000 11111 00000 00000",
        };

        static readonly Dictionary<char, int[]> Glyphs = Parse();
        static readonly int[] Blank = new int[GlyphHeight];

        /// <summary>The glyph's rows, top first; bit 4 of each row is the leftmost pixel.</summary>
        public static int[] Glyph(char c) => Glyphs.TryGetValue(char.ToUpperInvariant(c), out var rows) ? rows : Blank;

        static Dictionary<char, int[]> Parse()
        {
            var result = new Dictionary<char, int[]>();
            foreach (var pair in Shapes)
            {
                var rows = pair.Value.Split(' ');
                var bits = new int[GlyphHeight];
                for (var r = 0; r < GlyphHeight; r++)
                    foreach (var ch in rows[r])
                        bits[r] = bits[r] * 2 + (ch == '1' ? 1 : 0);
                result[pair.Key] = bits;
            }
            return result;
        }
    }
}
