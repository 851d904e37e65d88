using System;
using NUnit.Framework;

namespace NerfDatasetCreator.Tests
{
    [TestFixture]
    public class ExactArrayPoolTests
    {
        [Test]
        public void RentedArraysHaveExactlyThePoolLength()
        {
            var pool = new ExactArrayPool<float>(4097, 2);
            Assert.That(pool.Rent(), Has.Length.EqualTo(4097));
        }

        [Test]
        public void AReturnedArrayIsRentedAgainInsteadOfANewOne()
        {
            var pool = new ExactArrayPool<byte>(16, 2);
            var first = pool.Rent();
            pool.Return(first);
            Assert.That(pool.Rent(), Is.SameAs(first));
            Assert.That(pool.Created, Is.EqualTo(1));
        }

        [Test]
        public void RetainsAtMostMaxRetainedArrays()
        {
            var pool = new ExactArrayPool<byte>(8, 2);
            var arrays = new[] { pool.Rent(), pool.Rent(), pool.Rent() };
            foreach (var a in arrays) pool.Return(a);
            Assert.That(pool.Retained, Is.EqualTo(2));
            Assert.That(pool.Created, Is.EqualTo(3));
        }

        [Test]
        public void ReturningTheSameArrayTwiceKeepsOneCopy()
        {
            var pool = new ExactArrayPool<byte>(8, 4);
            var a = pool.Rent();
            pool.Return(a);
            pool.Return(a);
            Assert.That(pool.Retained, Is.EqualTo(1));
        }

        [Test]
        public void RefusesAnArrayOfAnotherLength()
        {
            var pool = new ExactArrayPool<byte>(8, 4);
            Assert.Throws<ArgumentException>(() => pool.Return(new byte[9]));
        }
    }
}
