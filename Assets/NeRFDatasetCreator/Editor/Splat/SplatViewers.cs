using System.Collections.Generic;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// A package that renders Gaussian splats in the Editor, as <i>Place trained splat</i> uses it: make or find its asset
    /// for a PLY and put a GameObject rendering it at a local transform under a parent. The plugin has no hard dependency on
    /// any such package: an optional assembly compiled only when the package is installed (an asmdef <c>versionDefines</c>
    /// entry plus <c>defineConstraints</c>) registers itself here when the editor loads.
    /// </summary>
    public interface ISplatViewer
    {
        /// <summary>The package's display name and id, e.g. "aras-p's Gaussian Splatting (org.nesnausk.gaussian-splatting)".</summary>
        string Name { get; }

        /// <summary>
        /// Places a GameObject named <paramref name="objectName"/> under <paramref name="parent"/> (null: the active scene's
        /// root) at <paramref name="local"/>, rendering the splat of <paramref name="plyPath"/>; reuses <paramref name="existing"/>
        /// when it is one of this viewer's objects.
        /// </summary>
        SplatViewerResult Place(string plyPath, Transform parent, SplatUnderParent local, string objectName, GameObject existing);
    }

    /// <summary>What a viewer did: the placed object (null when it could not) and what the user should read.</summary>
    public sealed class SplatViewerResult
    {
        public SplatViewerResult(GameObject placed, IReadOnlyList<string> lines)
        {
            Placed = placed;
            Lines = lines ?? new string[0];
        }

        public GameObject Placed { get; }
        public IReadOnlyList<string> Lines { get; }
    }

    /// <summary>The installed splat viewer, if any (<see cref="ISplatViewer"/>).</summary>
    public static class SplatViewers
    {
        /// <summary>aras-p's package: its id, and the git URL the Package Manager installs it from (the package lives in the
        /// repository's <c>package</c> folder, so the URL names it with <c>?path=/package</c>, Unity Manual "Install a UPM package
        /// from a Git URL", https://docs.unity3d.com/Manual/upm-ui-giturl.html).</summary>
        public const string ArasPPackage = "org.nesnausk.gaussian-splatting";
        public const string ArasPGitUrl = "https://github.com/aras-p/UnityGaussianSplatting.git?path=/package";

        /// <summary>The viewer an optional assembly registered, or null when no supported package is installed.</summary>
        public static ISplatViewer Installed { get; private set; }

        /// <summary>Called by an optional assembly's <c>[InitializeOnLoad]</c> class.</summary>
        public static void Register(ISplatViewer viewer) => Installed = viewer;

        /// <summary>What to tell a user who has no viewer installed.</summary>
        public static string InstallHint =>
            "No splat viewer is installed, so the transform is only shown. To see the splat in the scene, install aras-p's Gaussian Splatting: " +
            "Window ▸ Package Manager ▸ + ▸ Install package from git URL… " + ArasPGitUrl + " , then Place again.";
    }
}
