using System;
using System.Collections.Generic;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The concatenated data of a PNG's IDAT chunks read in place from the file's bytes (PNG spec §11.2.4: the zlib
    /// stream may be split across chunks), so that <see cref="PngReader"/> inflates it without copying it first.
    /// </summary>
    sealed class PngIdatStream : Stream
    {
        readonly byte[] _file;
        readonly List<int> _starts = new List<int>(), _lengths = new List<int>();
        long _length, _position;
        int _chunk, _inChunk; // where _position is: chunk index and offset in it

        public PngIdatStream(byte[] file) { _file = file; }

        public void Add(int start, int length)
        {
            if (length == 0) return;
            _starts.Add(start);
            _lengths.Add(length);
            _length += length;
        }

        public override bool CanRead => true;
        public override bool CanSeek => true;
        public override bool CanWrite => false;
        public override long Length => _length;

        public override long Position
        {
            get => _position;
            set
            {
                if (value < 0 || value > _length) throw new ArgumentOutOfRangeException(nameof(value));
                _position = value;
                _chunk = 0;
                _inChunk = 0;
                var left = value;
                while (_chunk < _lengths.Count && left >= _lengths[_chunk])
                {
                    left -= _lengths[_chunk];
                    _chunk++;
                }
                _inChunk = (int)left;
            }
        }

        public override int Read(byte[] buffer, int offset, int count) => Read(new Span<byte>(buffer, offset, count));

        public override int Read(Span<byte> buffer)
        {
            var done = 0;
            while (done < buffer.Length && _chunk < _lengths.Count)
            {
                var n = Math.Min(buffer.Length - done, _lengths[_chunk] - _inChunk);
                new ReadOnlySpan<byte>(_file, _starts[_chunk] + _inChunk, n).CopyTo(buffer.Slice(done));
                done += n;
                _inChunk += n;
                _position += n;
                if (_inChunk == _lengths[_chunk])
                {
                    _chunk++;
                    _inChunk = 0;
                }
            }
            return done;
        }

        public override long Seek(long offset, SeekOrigin origin)
        {
            Position = origin == SeekOrigin.Begin ? offset : origin == SeekOrigin.Current ? _position + offset : _length + offset;
            return _position;
        }

        public override void Flush() { }
        public override void SetLength(long value) => throw new NotSupportedException();
        public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();
    }
}
