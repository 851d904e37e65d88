using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// File names in the order a person reads them: runs of digits compare as numbers, so r_2.png comes before r_10.png
    /// (ordinal order puts r_10 first, and the file system's order is none at all). For the lists a refusal names.
    /// </summary>
    public sealed class FileNameOrder : IComparer<string>
    {
        public static readonly FileNameOrder Instance = new FileNameOrder();

        public int Compare(string a, string b)
        {
            if (ReferenceEquals(a, b)) return 0;
            if (a == null) return -1;
            if (b == null) return 1;
            int i = 0, j = 0;
            while (i < a.Length && j < b.Length)
            {
                if (char.IsDigit(a[i]) && char.IsDigit(b[j]))
                {
                    int startA = i, startB = j;
                    while (i < a.Length && char.IsDigit(a[i])) i++;
                    while (j < b.Length && char.IsDigit(b[j])) j++;
                    // Compare the numbers without parsing (any length): fewer significant digits is smaller.
                    var digitsA = a.Substring(startA, i - startA).TrimStart('0');
                    var digitsB = b.Substring(startB, j - startB).TrimStart('0');
                    if (digitsA.Length != digitsB.Length) return digitsA.Length.CompareTo(digitsB.Length);
                    var byValue = string.CompareOrdinal(digitsA, digitsB);
                    if (byValue != 0) return byValue;
                    continue;
                }
                if (a[i] != b[j]) return a[i].CompareTo(b[j]);
                i++;
                j++;
            }
            var byRest = (a.Length - i).CompareTo(b.Length - j);
            return byRest != 0 ? byRest : string.CompareOrdinal(a, b);
        }
    }
}
