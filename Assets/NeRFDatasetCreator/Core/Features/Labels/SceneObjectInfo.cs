using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// A plain description of one renderer in the capture, which the Unity layer fills and the label rules read
    /// (<see cref="LabelTable"/>): the chain of GameObjects from its scene root down to the renderer's own GameObject,
    /// and where the target sits on that chain. Only renderers the capture draws are described (the same cull rules as
    /// the other data passes).
    /// </summary>
    public sealed class SceneObjectInfo
    {
        /// <param name="chain">Scene root first, the renderer's GameObject last; at least one node.</param>
        /// <param name="targetDepth">
        /// How many nodes of <paramref name="chain"/> lead to the target inclusive: the target is
        /// <c>chain[targetDepth - 1]</c>. 0 when the target is the whole scene (an environment capture): the scene's roots
        /// are then the target's direct children.
        /// </param>
        /// <param name="sessionId">
        /// An identity valid for one capture only (the Unity layer passes the renderer's GameObject's <c>GetInstanceID()</c>):
        /// keeps an object's id when it moves in the hierarchy during a dynamic capture. Never written to a file; 0 for none.
        /// </param>
        public SceneObjectInfo(IReadOnlyList<SceneNode> chain, int targetDepth, long sessionId = 0)
        {
            if (chain == null) throw new ArgumentNullException(nameof(chain));
            if (chain.Count == 0) throw new ArgumentException("a renderer's chain holds at least its own GameObject", nameof(chain));
            foreach (var node in chain)
                if (node == null) throw new ArgumentException("a chain holds no null nodes", nameof(chain));
            if (targetDepth < 0 || targetDepth > chain.Count)
                throw new ArgumentOutOfRangeException(nameof(targetDepth), targetDepth, "the target is on the renderer's chain (0 = the whole scene)");
            Chain = chain;
            TargetDepth = targetDepth;
            SessionId = sessionId;
        }

        public IReadOnlyList<SceneNode> Chain { get; }

        public int TargetDepth { get; }

        public long SessionId { get; }

        /// <summary>The renderer's own GameObject.</summary>
        public SceneNode Renderer => Chain[Chain.Count - 1];
    }
}
