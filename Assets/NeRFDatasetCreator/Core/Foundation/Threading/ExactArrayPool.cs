using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Recycles arrays of one exact length (the size of one view's pass), so that a long run allocates a handful of
    /// large buffers instead of one per view. Unlike <c>ArrayPool&lt;T&gt;.Shared</c> it never hands out a longer
    /// array, so a buffer's <c>Length</c> is always the pixel count times the channel count. Thread-safe: the
    /// capture loop rents on the main thread, writers return on worker threads.
    /// </summary>
    public sealed class ExactArrayPool<T>
    {
        readonly Stack<T[]> _free = new Stack<T[]>();
        readonly object _lock = new object();

        public ExactArrayPool(int length, int maxRetained)
        {
            InvalidParameterException.ThrowIfAny(
                ValidationProblem.OutsideRange(nameof(length), length, 0, int.MaxValue),
                ValidationProblem.OutsideRange(nameof(maxRetained), maxRetained, 0, 1024));
            Length = length;
            MaxRetained = maxRetained;
        }

        public int Length { get; }
        public int MaxRetained { get; }

        /// <summary>Arrays created so far (a run whose memory is flat stops growing this early).</summary>
        public int Created { get; private set; }

        public int Retained
        {
            get { lock (_lock) return _free.Count; }
        }

        /// <summary>An array of exactly <see cref="Length"/> elements; its contents are whatever was there before.</summary>
        public T[] Rent()
        {
            lock (_lock)
            {
                if (_free.Count > 0) return _free.Pop();
                Created++;
            }
            return new T[Length];
        }

        /// <summary>Gives an array back; arrays beyond <see cref="MaxRetained"/> are left to the garbage collector.</summary>
        public void Return(T[] array)
        {
            if (array == null) return;
            if (array.Length != Length)
                throw new ArgumentException(
                    $"The array has {array.Length} elements but this pool holds arrays of {Length}.", nameof(array));
            lock (_lock)
            {
                if (_free.Count < MaxRetained && !_free.Contains(array)) _free.Push(array);
            }
        }
    }
}
