using System.Collections.Generic;
using System.Linq;

namespace NerfDatasetCreator.Tests
{
    /// <summary>
    /// A small described hierarchy for the label tests (objects as the Unity layer describes them; nothing is rendered):
    /// the target "City" (scene root 0) holds two instances of a car
    /// prefab (each a body and wheel renderers), a tree and a lamp; "Sun" (scene root 1) is outside the target.
    /// <code>
    /// City [0]            target
    ///   Car [0]           prefab Assets/Props/Car.prefab, tag Vehicle, layer Props
    ///     Body [0]        renderer
    ///     Wheel [1]       renderer
    ///   Tree [1]          renderer, tag Untagged, layer Default
    ///   Car [2]           prefab Assets/Props/Car.prefab, tag Vehicle, layer Props
    ///     Body [0]        renderer
    ///   Lamp [3]          renderer, tag Light, layer Props
    /// </code>
    /// </summary>
    static class LabelHierarchy
    {
        public static SceneNode City => new SceneNode("City", 0, "Untagged", "Default");

        public static SceneNode Car(int sibling) => new SceneNode("Car", sibling, "Vehicle", "Props", "Assets/Props/Car.prefab");

        public static SceneObjectInfo Renderer(long session, params SceneNode[] chain) => new SceneObjectInfo(chain, 1, session);

        public static List<SceneObjectInfo> Renderers() => new List<SceneObjectInfo>
        {
            Renderer(11, City, Car(0), new SceneNode("Body", 0, "Vehicle", "Props")),
            Renderer(12, City, Car(0), new SceneNode("Wheel", 1, "Vehicle", "Props")),
            Renderer(13, City, new SceneNode("Tree", 1, "Untagged", "Default")),
            Renderer(14, City, Car(2), new SceneNode("Body", 0, "Vehicle", "Props")),
            Renderer(15, City, new SceneNode("Lamp", 3, "Light", "Props")),
        };

        public static LabelSettings Settings(InstanceRule instances, ClassSource classFrom, params ClassRule[] rules) =>
            new LabelSettings { Enabled = true, Instances = instances, ClassFrom = classFrom, Classes = rules.ToList() };
    }
}
