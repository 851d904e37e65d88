using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Whole-scene labels with several loaded scenes. A root's sibling index counts among its own scene's roots only
    /// (Unity: <c>Transform.GetSiblingIndex</c> of a root is its place in <c>Scene.GetRootGameObjects</c>), so two scenes
    /// made from one template (<c>Room_01</c>, <c>Room_02</c>, each with <c>0:Room/0:Wall</c>) would give distinct objects
    /// one key and one id. <see cref="InScene"/> puts a node naming the scene on top of the chain, as Unity's hierarchy
    /// window shows it: the scene's name and its place among the loaded scenes (which also tells two same-named scenes
    /// from different folders apart). A capture with one loaded scene is left as it is (<see cref="Qualifies"/>), so its
    /// keys, paths and ids are the ones earlier versions wrote.
    /// </summary>
    public static class LabelScenes
    {
        /// <summary>Unity's name for a scene never saved (its <c>Scene.name</c> is empty).</summary>
        public const string Untitled = "Untitled";

        /// <summary>Whether a whole-scene capture's chains need their scene: only when more than one scene is loaded.</summary>
        public static bool Qualifies(int loadedScenes) => loadedScenes > 1;

        /// <summary>
        /// <paramref name="info"/> with a node for its scene on top: the path becomes <c>Room_01/Room/Wall</c>, the sibling
        /// path starts with the scene's place among the loaded scenes (the hierarchy window's order, so ids still follow it),
        /// and the target depth grows by one, so the <c>child</c> rule still means "a scene root" and the scene node is never
        /// an object of its own.
        /// </summary>
        public static SceneObjectInfo InScene(SceneObjectInfo info, string sceneName, int sceneIndex)
        {
            if (info == null) throw new ArgumentNullException(nameof(info));
            if (sceneIndex < 0) throw new ArgumentOutOfRangeException(nameof(sceneIndex), sceneIndex, "a loaded scene's index is never negative");
            var chain = new List<SceneNode>(info.Chain.Count + 1) { new SceneNode(string.IsNullOrEmpty(sceneName) ? Untitled : sceneName, sceneIndex) };
            chain.AddRange(info.Chain);
            return new SceneObjectInfo(chain, info.TargetDepth + 1, info.SessionId);
        }
    }
}
