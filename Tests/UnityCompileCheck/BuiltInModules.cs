using System;
using System.Collections.Generic;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace NerfDatasetCreator.UnityCompileCheck
{
    /// <summary>
    /// Which built-in module (com.unity.modules.*) declares a Unity type. Unity drops the types of a module the
    /// project disables, so a package must declare every module whose types it uses. The reference assemblies are
    /// one assembly per editor, so the module of a type comes from this table (Unity's per-module assemblies,
    /// UnityEngine.&lt;Module&gt;Module.dll, in an install); it lists the modules this plugin may plausibly touch.
    /// </summary>
    static class BuiltInModules
    {
        static readonly (string Prefix, string Module)[] Table =
        {
            ("UnityEngine.GUI", "com.unity.modules.imgui"),
            ("UnityEngine.GUILayout", "com.unity.modules.imgui"),
            ("UnityEngine.GUILayoutOption", "com.unity.modules.imgui"),
            ("UnityEngine.GUILayoutUtility", "com.unity.modules.imgui"),
            ("UnityEngine.GUIContent", "com.unity.modules.imgui"),
            ("UnityEngine.GUIStyle", "com.unity.modules.imgui"),
            ("UnityEngine.GUIStyleState", "com.unity.modules.imgui"),
            ("UnityEngine.GUISkin", "com.unity.modules.imgui"),
            ("UnityEngine.GUIUtility", "com.unity.modules.imgui"),
            ("UnityEngine.Event", "com.unity.modules.imgui"),
            ("UnityEngine.EventType", "com.unity.modules.imgui"),
            ("UnityEngine.ImageConversion", "com.unity.modules.imageconversion"),
            ("UnityEngine.JsonUtility", "com.unity.modules.jsonserialize"),
            ("UnityEditor.EditorJsonUtility", "com.unity.modules.jsonserialize"),
            ("UnityEngine.ParticleSystem", "com.unity.modules.particlesystem"),
            ("UnityEngine.ParticleSystemRenderer", "com.unity.modules.particlesystem"),
            ("UnityEngine.ParticleSystemStopBehavior", "com.unity.modules.particlesystem"),
            ("UnityEngine.Terrain", "com.unity.modules.terrain"),
            ("UnityEngine.TerrainData", "com.unity.modules.terrain"),
            ("UnityEngine.Physics", "com.unity.modules.physics"),
            ("UnityEngine.Collider", "com.unity.modules.physics"),
            ("UnityEngine.BoxCollider", "com.unity.modules.physics"),
            ("UnityEngine.Rigidbody", "com.unity.modules.physics"),
            ("UnityEngine.Animator", "com.unity.modules.animation"),
            ("UnityEngine.Animation", "com.unity.modules.animation"),
            ("UnityEngine.RuntimeAnimatorController", "com.unity.modules.animation"),
            ("UnityEngine.AnimationClip", "com.unity.modules.animation"),
            ("UnityEngine.Playables.PlayableDirector", "com.unity.modules.director"),
            ("UnityEngine.AudioListener", "com.unity.modules.audio"),
            ("UnityEngine.AudioSource", "com.unity.modules.audio"),
            ("UnityEngine.UIElements.", "com.unity.modules.uielements"),
            ("UnityEngine.Video.", "com.unity.modules.video"),
        };

        /// <summary>The module of a type: entries name a type (and its nested types) or, ending in '.', a namespace.</summary>
        public static string ModuleOf(ITypeSymbol type)
        {
            var name = type.OriginalDefinition.ToDisplayString(SymbolDisplayFormat.FullyQualifiedFormat).Replace("global::", "");
            foreach (var (entry, module) in Table)
                if (entry.EndsWith(".", StringComparison.Ordinal)
                        ? name.StartsWith(entry, StringComparison.Ordinal)
                        : name == entry || name.StartsWith(entry + ".", StringComparison.Ordinal))
                    return module;
            return null;
        }

        /// <summary>Every module whose types a compilation's code names, with one place each is used.</summary>
        public static SortedDictionary<string, string> UsedBy(Compilation compilation, string root)
        {
            var used = new SortedDictionary<string, string>(StringComparer.Ordinal);
            foreach (var tree in compilation.SyntaxTrees)
            {
                var model = compilation.GetSemanticModel(tree);
                foreach (var node in tree.GetRoot().DescendantNodes().OfType<SimpleNameSyntax>())
                {
                    var symbol = model.GetSymbolInfo(node).Symbol;
                    var type = symbol as ITypeSymbol ?? symbol?.ContainingType;
                    if (type == null) continue;
                    var module = ModuleOf(type);
                    if (module != null && !used.ContainsKey(module))
                        used[module] = AsmdefCompiler.Where(node.GetLocation(), root) + " uses " + type.ToDisplayString();
                }
            }
            return used;
        }
    }
}
