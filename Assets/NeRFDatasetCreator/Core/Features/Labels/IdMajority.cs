namespace NerfDatasetCreator
{
    /// <summary>
    /// The id maps' supersampling rule: each output pixel is one id, never a blend. A pixel is foreground when at
    /// least half of its k×k samples hit a labelled object — the threshold at which the mask image reads 128 or more,
    /// so the instance map's foreground is the mask's — and then takes the id covering the most of its samples; a tie
    /// between ids goes to the smaller id. With a class lookup the same rule runs on the samples' class ids (the
    /// semantic map): a pixel half car, half background is "car" even when two cars share it.
    /// </summary>
    public static class IdMajority
    {
        /// <summary>
        /// Writes OutputWidth×OutputHeight ids into <paramref name="ids"/>, top row first (PNG order). With
        /// <paramref name="classOfInstance"/> (<see cref="LabelTable.ClassOfInstance"/>), each sample's instance id is
        /// first replaced by its class id (ids beyond the lookup count as class 0).
        /// </summary>
        public static void Resolve(RawFrame frame, ushort[] ids, ushort[] classOfInstance = null)
        {
            if (frame == null) throw new System.ArgumentNullException(nameof(frame));
            var problems = frame.Validate();
            if (frame.InstanceIds == null)
                problems.Add(new ValidationProblem("frame.InstanceIds", "null", "is required: this step reads the id pass.", "Read the id pass back into this array first."));
            if (problems.Count > 0) throw new InvalidParameterException(problems);
            int ow = frame.OutputWidth, oh = frame.OutputHeight, k = frame.Supersampling, width = frame.Width;
            RawFrame.RequireOutput("ids", ids, (long)ow * oh, "ids (1 per output pixel)");
            var samples = frame.InstanceIds;
            if (k == 2)
            {
                ResolveTwoByTwo(samples, width, ow, oh, ids, classOfInstance);
                return;
            }
            var block = new ushort[k * k];
            for (int oy = 0; oy < oh; oy++)
            {
                int blockRow = RowOrder.SourceBlockRow(oy, oh, k);
                int o = oy * ow;
                for (int ox = 0; ox < ow; ox++)
                {
                    int first = blockRow * width + ox * k, n = 0;
                    for (int dy = 0; dy < k; dy++)
                    {
                        int p = first + dy * width;
                        for (int dx = 0; dx < k; dx++) block[n++] = Map(samples[p + dx], classOfInstance);
                    }
                    ids[o + ox] = Majority(block, n);
                }
            }
        }

        /// <summary>
        /// The capture's default supersampling 2 without the general loop's calls (Mono inlines none): a block of one id
        /// (all of a view but its edges) is written at once; only mixed blocks go through <see cref="Majority"/>.
        /// </summary>
        static void ResolveTwoByTwo(ushort[] samples, int width, int ow, int oh, ushort[] ids, ushort[] lookup)
        {
            var block = new ushort[4];
            var classes = lookup ?? new ushort[0];
            var mapped = lookup != null;
            for (int oy = 0; oy < oh; oy++)
            {
                int p = RowOrder.SourceBlockRow(oy, oh, 2) * width, q = p + width, o = oy * ow, end = o + ow;
                for (; o < end; o++, p += 2, q += 2)
                {
                    ushort a = samples[p], b = samples[p + 1], c = samples[q], d = samples[q + 1];
                    if (mapped)
                    {
                        a = a < classes.Length ? classes[a] : (ushort)0;
                        b = b < classes.Length ? classes[b] : (ushort)0;
                        c = c < classes.Length ? classes[c] : (ushort)0;
                        d = d < classes.Length ? classes[d] : (ushort)0;
                    }
                    if (a == b && a == c && a == d)
                    {
                        ids[o] = a;
                        continue;
                    }
                    block[0] = a;
                    block[1] = b;
                    block[2] = c;
                    block[3] = d;
                    ids[o] = Majority(block, 4);
                }
            }
        }

        static ushort Map(ushort id, ushort[] lookup)
        {
            if (lookup == null) return id;
            return id < lookup.Length ? lookup[id] : (ushort)0;
        }

        /// <summary>The rule on one block of <paramref name="n"/> sample ids (the first n of <paramref name="block"/>).</summary>
        public static ushort Majority(ushort[] block, int n)
        {
            ushort first = block[0];
            var uniform = true;
            var foreground = 0;
            for (var i = 0; i < n; i++)
            {
                if (block[i] != first) uniform = false;
                if (block[i] != 0) foreground++;
            }
            if (uniform) return first;
            if (2 * foreground < n) return 0;
            // At most 16 samples: count by scanning, no dictionary.
            ushort best = 0;
            var bestCount = 0;
            for (var i = 0; i < n; i++)
            {
                var id = block[i];
                if (id == 0) continue;
                var count = 0;
                for (var j = 0; j < n; j++) if (block[j] == id) count++;
                if (count > bestCount || (count == bestCount && id < best))
                {
                    best = id;
                    bestCount = count;
                }
            }
            return best;
        }
    }
}
