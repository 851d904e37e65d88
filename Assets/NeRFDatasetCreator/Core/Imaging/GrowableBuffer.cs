using System;
using System.IO;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A write-only stream into a byte array that grows by doubling and is kept for the next use, so a thread that
    /// encodes frame after frame stops allocating once the buffer has reached its working size. Unlike
    /// MemoryStream it can be reset without giving its array away.
    /// </summary>
    internal sealed class GrowableBuffer : Stream
    {
        byte[] buffer = new byte[1 << 16];
        int length;

        public byte[] Array => buffer;
        public override long Length => length;

        public void Reset() => length = 0;

        /// <summary>Makes room for <paramref name="count"/> more bytes and returns the offset they go at.</summary>
        public int Reserve(int count)
        {
            int needed = checked(length + count);
            if (needed > buffer.Length)
            {
                long size = buffer.Length;
                while (size < needed) size *= 2;
                var bigger = new byte[Math.Min(size, int.MaxValue)];
                System.Buffer.BlockCopy(buffer, 0, bigger, 0, length);
                buffer = bigger;
            }
            int at = length;
            length = needed;
            return at;
        }

        public override void Write(byte[] data, int offset, int count)
        {
            int at = Reserve(count);
            System.Buffer.BlockCopy(data, offset, buffer, at, count);
        }

        public override void WriteByte(byte value) => buffer[Reserve(1)] = value;

        public override bool CanRead => false;
        public override bool CanSeek => false;
        public override bool CanWrite => true;
        public override void Flush() { }

        public override long Position
        {
            get => length;
            set => throw new NotSupportedException();
        }

        public override int Read(byte[] data, int offset, int count) => throw new NotSupportedException();
        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
        public override void SetLength(long value) => throw new NotSupportedException();
    }
}
