using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>Decoded depth maps by view number, least recently used dropped first once over a byte budget.</summary>
    sealed class DepthCache
    {
        readonly long _budget;
        long _bytes;
        readonly LinkedList<KeyValuePair<int, ushort[]>> _order = new LinkedList<KeyValuePair<int, ushort[]>>();
        readonly Dictionary<int, LinkedListNode<KeyValuePair<int, ushort[]>>> _nodes = new Dictionary<int, LinkedListNode<KeyValuePair<int, ushort[]>>>();

        public DepthCache(long budgetBytes) { _budget = budgetBytes; }

        public ushort[] Get(int view)
        {
            if (!_nodes.TryGetValue(view, out var node)) return null;
            _order.Remove(node);
            _order.AddFirst(node);
            return node.Value.Value;
        }

        public void Put(int view, ushort[] depth)
        {
            if (_nodes.ContainsKey(view)) return;
            _nodes[view] = _order.AddFirst(new KeyValuePair<int, ushort[]>(view, depth));
            _bytes += depth.Length * 2L;
            while (_bytes > _budget && _order.Count > 1)
            {
                var last = _order.Last;
                _order.RemoveLast();
                _nodes.Remove(last.Value.Key);
                _bytes -= last.Value.Value.Length * 2L;
            }
        }
    }
}
