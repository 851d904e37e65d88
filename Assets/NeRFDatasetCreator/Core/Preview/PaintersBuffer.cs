using System;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The painter's algorithm without the sort: drawing items in any order, each pixel keeps the colour of the item a
    /// painter drawing them in order would have drawn last — the one with the greatest (depth, index, layer) in that
    /// order. <see cref="RgbCanvas"/> draws by overwriting pixels, so the picture is the very one the sorted drawing
    /// gives, at a fixed cost per pixel of the region (13 bytes) instead of a sorted copy of every item (the rig
    /// picture of 300 000 cameras sorted 20 bytes each, twice).
    /// </summary>
    public sealed class PaintersBuffer
    {
        readonly int _left, _top, _width, _height;
        readonly double[] _depth;
        readonly int[] _index;
        readonly byte[] _layer; // 0: nothing drawn yet; else layer + 1
        readonly bool _descending;
        double _itemDepth;
        int _itemIndex;
        byte _itemLayer;

        /// <param name="descending">Whether greater depths are drawn first (a painter draws from far to near).</param>
        public PaintersBuffer(int left, int top, int width, int height, bool descending)
        {
            _left = left;
            _top = top;
            _width = width;
            _height = height;
            _depth = new double[width * height];
            _index = new int[width * height];
            _layer = new byte[width * height];
            _descending = descending;
        }

        /// <summary>What the canvas draws next belongs to this item: its depth, its index (ties in depth go by index) and its layer within the item (later layers over earlier ones).</summary>
        public void Item(double depth, int index, int layer)
        {
            _itemDepth = depth;
            _itemIndex = index;
            _itemLayer = (byte)(layer + 1);
        }

        /// <summary>The canvas filter: draws the pixel when the current item comes at or after the pixel's last one in painter's order.</summary>
        public bool Accept(int x, int y)
        {
            var px = x - _left;
            var py = y - _top;
            if (px < 0 || py < 0 || px >= _width || py >= _height) return true; // outside the buffered region: drawn as given
            var i = py * _width + px;
            if (_layer[i] != 0)
            {
                // The same comparison as a painter's sort: depth (ascending or descending, CompareTo's order, NaN first), then index.
                var byDepth = _descending ? _depth[i].CompareTo(_itemDepth) : _itemDepth.CompareTo(_depth[i]);
                if (byDepth < 0) return false;
                if (byDepth == 0)
                {
                    if (_itemIndex < _index[i]) return false;
                    if (_itemIndex == _index[i] && _itemLayer < _layer[i]) return false;
                }
            }
            _depth[i] = _itemDepth;
            _index[i] = _itemIndex;
            _layer[i] = _itemLayer;
            return true;
        }
    }
}
