using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;
using Object = UnityEngine.Object;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// The isolated world a capture renders: an editor preview scene holding copies of the target (or of every root
    /// object), copies of the scene's lights and the hidden capture camera. The user's scenes are only read, never
    /// written: no object, layer, material or active state of theirs changes, so their dirty flags stay as they were.
    /// Everything here is HideAndDontSave and goes away with <see cref="Dispose"/>.
    /// </summary>
    sealed class CaptureStage : IDisposable
    {
        readonly List<Renderer> _dataPassRenderers = new List<Renderer>();
        readonly Dictionary<Renderer, RendererLabelIds> _copyLabels = new Dictionary<Renderer, RendererLabelIds>();
        Scene _scene;
        GameObject _root;
        GameObject _cameraObject;
        SceneLighting _lighting;

        public Camera Camera { get; private set; }

        /// <summary>The copies' mesh and skinned-mesh renderers the mask, depth and normal passes draw (LOD 0 only).</summary>
        public IReadOnlyList<Renderer> DataPassRenderers => _dataPassRenderers;

        /// <summary>The ids of the copies' renderers, taken from their sources' (<see cref="CaptureOptions.Labels"/>); empty without labels.</summary>
        public IReadOnlyDictionary<Renderer, RendererLabelIds> CopyLabels => _copyLabels;

        /// <summary>The parent of every copy in the preview scene.</summary>
        public GameObject Root => _root;

        /// <summary>Renderers the data passes cannot draw (particles, lines, sprites…, terrains): absent from mask, depth and normal.</summary>
        public int UnsupportedRendererCount { get; private set; }

        /// <summary>False once anything the stage owns was destroyed from outside (a scene reload, a script).</summary>
        public bool IsIntact => _root != null && Camera != null && _scene.IsValid();

        public CaptureStage(GameObject target, CaptureOptions options)
        {
            try
            {
                _lighting = new SceneLighting(); // the user's active scene's, read before anything changes
                _scene = EditorSceneManager.NewPreviewScene();
                if (!_scene.IsValid()) throw new CaptureException("Unity could not create the preview scene the capture renders in.");

                // Copies are made under an inactive root and their scripts are disabled before it is activated, so
                // OnEnable/Update of the user's [ExecuteAlways] scripts never run on them. (Awake still does: Unity calls
                // it on disabled components when their object becomes active.)
                _root = NewHiddenObject("NeRF Dataset Creator capture");
                _root.SetActive(false);

                var copies = new List<KeyValuePair<GameObject, GameObject>>();
                foreach (var source in Sources(target, options.Isolation))
                {
                    var copy = Object.Instantiate(source, _root.transform, true);
                    copy.name = source.name;
                    copies.Add(new KeyValuePair<GameObject, GameObject>(source, copy));
                    if (options.Isolation == CaptureIsolation.TargetOnly) copy.SetActive(true);
                    Neutralise(copy);
                    LodZero.Apply(source, copy);
                    RenderAsPosed(copy);
                    if (options.Isolation == CaptureIsolation.WholeScene) DisableProbesWithoutCubemap(copy);
                    if (options.Labels != null) CopyLabelsOf(source, copy, options.Labels);
                }
                if (options.Isolation == CaptureIsolation.TargetOnly && options.CopySceneLights)
                    CopySceneLights(target);
                // Lights under the target and, in whole-scene mode, every light arrive through Instantiate with their
                // bake type and last bake's output: without lightmaps in this scene they must all be realtime.
                CaptureLights.MakeAllRealtime(_root);

                CollectRenderers();
                _root.SetActive(true);
                // After activation: an inactive particle system holds no particles.
                foreach (var pair in copies) CopyParticles(pair.Key, pair.Value);

                _cameraObject = NewHiddenObject("NeRF Dataset Creator camera", typeof(Camera));
                Camera = _cameraObject.GetComponent<Camera>();
                ConfigureCamera(Camera, options, _scene);
            }
            catch
            {
                Dispose();
                throw;
            }
        }

        /// <summary>Every light among the capture's copies, enabled or not: what a relighting condition switches off.</summary>
        public Light[] Lights => _root == null ? new Light[0] : _root.GetComponentsInChildren<Light>(true);

        /// <summary>Renders with the user's ambient, reflection and fog settings until <see cref="UnpinLighting"/> (<see cref="SceneLighting"/>).</summary>
        public void PinLighting() => _lighting?.Pin(_scene);

        public void UnpinLighting() => _lighting?.Unpin();

        GameObject NewHiddenObject(string name, params Type[] components)
        {
            var go = EditorUtility.CreateGameObjectWithHideFlags(name, HideFlags.HideAndDontSave, components);
            SceneManager.MoveGameObjectToScene(go, _scene);
            return go;
        }

        static IEnumerable<GameObject> Sources(GameObject target, CaptureIsolation isolation)
        {
            if (isolation == CaptureIsolation.TargetOnly)
            {
                yield return target;
                yield break;
            }
            for (var i = 0; i < SceneManager.sceneCount; i++)
            {
                var scene = SceneManager.GetSceneAt(i);
                if (!scene.isLoaded) continue;
                foreach (var root in scene.GetRootGameObjects())
                {
                    // Editor-internal objects (DontSave) are not part of the user's scene.
                    if ((root.hideFlags & HideFlags.DontSave) != 0 || !root.activeInHierarchy) continue;
                    yield return root;
                }
            }
        }

        /// <summary>
        /// A particle system's live particles are simulation state, not serialized settings: they are carried over
        /// explicitly (GetParticles/SetParticles), so that the copy shows what the user's system shows now. Instantiate
        /// keeps the hierarchy, so the n-th system of the copy is the n-th of the source.
        /// </summary>
        static void CopyParticles(GameObject source, GameObject copy)
        {
            var from = source.GetComponentsInChildren<ParticleSystem>(true);
            var to = copy.GetComponentsInChildren<ParticleSystem>(true);
            for (var i = 0; i < from.Length && i < to.Length; i++)
            {
                var count = from[i].particleCount;
                if (count == 0) continue;
                var particles = new ParticleSystem.Particle[count];
                count = from[i].GetParticles(particles);
                to[i].SetParticles(particles, count);
            }
        }

        /// <summary>Copies carry the user's components; only rendering ones may act. Cameras and scripts are switched off.</summary>
        static void Neutralise(GameObject copy)
        {
            foreach (var t in copy.GetComponentsInChildren<Transform>(true)) t.gameObject.hideFlags = HideFlags.HideAndDontSave;
            foreach (var camera in copy.GetComponentsInChildren<Camera>(true)) camera.enabled = false;
            foreach (var script in copy.GetComponentsInChildren<MonoBehaviour>(true))
                if (script != null) script.enabled = false;
        }

        /// <summary>
        /// The copies are rendered by hand, many times within one editor update (a blocking run renders every view in
        /// one; a background slice several), and a dynamic capture poses them between those renders. Unity skins a
        /// SkinnedMeshRenderer once per update unless <c>forceMatrixRecalculationPerRender</c> is set ("This property
        /// must be set in cases where the user would like to manually render a skinned mesh multiple times within a
        /// single update, an example of this would be rendering out the results of an animation to a texture",
        /// Scripting API SkinnedMeshRenderer.forceMatrixRecalculationPerRender; public in UnityCsReference 2022.3
        /// Runtime/Export/Graphics/GraphicsRenderers.bindings.cs:372, 6000.0 :384): without it every view of an update
        /// would show the first view's pose. An Animator culled by visibility (Cull Update Transforms / Cull Completely,
        /// "Animation is completely disabled when renderers are not visible", Scripting API AnimatorCullingMode) would
        /// not pose a copy that no Scene or Game view ever shows: the copies always animate. Only copies change.
        /// </summary>
        static void RenderAsPosed(GameObject copy)
        {
            foreach (var skinned in copy.GetComponentsInChildren<SkinnedMeshRenderer>(true))
            {
                skinned.forceMatrixRecalculationPerRender = true;
                // Review S3-5: the data passes' DrawRenderer relies on the colour render having skinned this renderer
                // for this view; with stale bounds it could be culled in colour while its geometry is in view, and the
                // data passes would draw the previous view's skin. Skinning off-screen too keeps bounds and skin current
                // (UCR 2022.3 GraphicsRenderers.bindings.cs:371, 6000.0 :383).
                skinned.updateWhenOffscreen = true;
            }
            foreach (var animator in copy.GetComponentsInChildren<Animator>(true))
                animator.cullingMode = AnimatorCullingMode.AlwaysAnimate;
        }

        /// <summary>
        /// Review S3-10: in whole-scene mode the copies bring the scene's reflection probes. A baked probe's cubemap
        /// belongs to the scene's lighting data; a copy without one (<c>ReflectionProbe.texture</c> null, UCR 2022.3/6000.0
        /// <c>Runtime/Export/Camera/ReflectionProbe.bindings.cs:60</c>) would still be picked for the renderers in its
        /// volume and take away the default reflection that <see cref="SceneLighting"/> pins. Such copies are disabled
        /// (only copies change); realtime and custom probes are left as they are.
        /// </summary>
        static void DisableProbesWithoutCubemap(GameObject copy)
        {
            foreach (var probe in copy.GetComponentsInChildren<ReflectionProbe>(true))
                if (probe.mode == UnityEngine.Rendering.ReflectionProbeMode.Baked && probe.texture == null) probe.enabled = false;
        }

        /// <summary>
        /// A preview scene renders only what is in it, so the scene's lights are brought along as copies at the same
        /// world pose. Lights under the target are already copied with it. Lights baked into lightmaps would light
        /// nothing on a copy (it has no lightmap in this scene), so every copy is realtime. The Light's properties are
        /// copied one by one (not EditorUtility.CopySerialized, which would also bring its bake output); URP's
        /// per-light component is copied whole (<see cref="CaptureLights.CopyPipelineData"/>).
        /// </summary>
        void CopySceneLights(GameObject target)
        {
            foreach (var light in Object.FindObjectsByType<Light>(FindObjectsInactive.Exclude, FindObjectsSortMode.None))
            {
                if (light == null || !light.isActiveAndEnabled) continue;
                if ((light.gameObject.hideFlags & HideFlags.DontSave) != 0) continue;
                if (EditorSceneManager.IsPreviewSceneObject(light)) continue;
                if (light.transform.IsChildOf(target.transform)) continue;
                var go = NewHiddenObject("Light copy: " + light.name, typeof(Light));
                go.transform.SetParent(_root.transform, false);
                go.transform.SetPositionAndRotation(light.transform.position, light.transform.rotation);
                try
                {
                    CopyLight(light, go.GetComponent<Light>());
                    CaptureLights.CopyPipelineData(light, go.GetComponent<Light>());
                }
                catch (Exception e)
                {
                    // Some setters validate against the pipeline (e.g. shadow types); one odd light must not stop a capture.
                    Object.DestroyImmediate(go);
                    Debug.LogWarning("NeRF Dataset Creator: the light '" + light.name + "' could not be copied into the capture and is left out: " + e.Message);
                }
            }
        }

        static void CopyLight(Light from, Light to)
        {
            to.type = from.type;
            to.color = from.color;
            to.colorTemperature = from.colorTemperature;
            to.useColorTemperature = from.useColorTemperature;
            to.intensity = from.intensity;
            to.bounceIntensity = from.bounceIntensity;
            to.range = from.range;
            to.spotAngle = from.spotAngle;
            to.innerSpotAngle = from.innerSpotAngle;
            to.areaSize = from.areaSize;
            to.shadows = from.shadows;
            to.shadowStrength = from.shadowStrength;
            to.shadowBias = from.shadowBias;
            to.shadowNormalBias = from.shadowNormalBias;
            to.shadowNearPlane = from.shadowNearPlane;
            to.cullingMask = from.cullingMask;
            to.renderingLayerMask = from.renderingLayerMask;
            to.cookie = from.cookie;
            to.cookieSize = from.cookieSize;
            to.renderMode = from.renderMode;
            // Review S3-9: the Built-in pipeline's per-light shadow quality, the shadow-caster mode, the bounding-sphere
            // override and (2022.3; obsolete in 6000 where Light.type carries it) the spot shape (UCR 2022.3
            // Runtime/Export/Graphics/Light.bindings.cs:36 shadowResolution; GraphicsComponents.bindings.cs:82 shape,
            // :92-93 bounding sphere, :96 shadowCustomResolution, :109 lightShadowCasterMode; 6000.0 :37, :96-97, :101, :115).
            to.shadowResolution = from.shadowResolution;
            to.shadowCustomResolution = from.shadowCustomResolution;
            to.lightShadowCasterMode = from.lightShadowCasterMode;
            to.useBoundingSphereOverride = from.useBoundingSphereOverride;
            to.boundingSphereOverride = from.boundingSphereOverride;
#if !UNITY_6000_0_OR_NEWER
            to.shape = from.shape;
#endif
            to.lightmapBakeType = LightmapBakeType.Realtime;
        }

        void CollectRenderers()
        {
            // Renderers beyond LOD 0 are already disabled on the copies (LodZero.Apply), so the data passes skip them.
            foreach (var renderer in _root.GetComponentsInChildren<Renderer>(true))
            {
                if (renderer is MeshRenderer || renderer is SkinnedMeshRenderer) _dataPassRenderers.Add(renderer);
                else UnsupportedRendererCount++;
            }
            // Terrains draw without a Renderer. Recognised by type name: UnityEngine.Terrain lives in the Terrain
            // built-in module, which a project may disable (this package's own development project does), and
            // naming the type would then not compile.
            foreach (var behaviour in _root.GetComponentsInChildren<Behaviour>(true))
                if (behaviour != null && behaviour.GetType().FullName == TerrainTypeName) UnsupportedRendererCount++;
        }

        const string TerrainTypeName = "UnityEngine.Terrain";

        /// <summary>
        /// Gives each renderer of <paramref name="copy"/> the ids of the renderer it was copied from. <c>Object.Instantiate</c>
        /// clones the whole hierarchy with its components (Scripting API Object.Instantiate, 2022.3: "When you clone a
        /// GameObject or Component, all child objects and components are also cloned"), and nothing here adds or removes a renderer, so the n-th renderer of the
        /// copy in <c>GetComponentsInChildren</c> order is the n-th of the source (as <see cref="CopyParticles"/> relies on);
        /// the names are compared too, and a mismatch stops the capture rather than label an object with another's id.
        /// </summary>
        void CopyLabelsOf(GameObject source, GameObject copy, IReadOnlyDictionary<Renderer, RendererLabelIds> labels)
        {
            var from = source.GetComponentsInChildren<Renderer>(true);
            var to = copy.GetComponentsInChildren<Renderer>(true);
            if (from.Length != to.Length)
                throw new CaptureException("The copy of '" + source.name + "' has " + to.Length + " renderers where the original has " +
                    from.Length + ", so the labels cannot be matched to them. Please report this with your Unity version.");
            for (var i = 0; i < from.Length; i++)
            {
                if (from[i].name != to[i].name || from[i].GetType() != to[i].GetType())
                    throw new CaptureException("The copy's renderer '" + to[i].name + "' does not match the original's '" + from[i].name +
                        "', so the labels cannot be matched to them. Please report this with your Unity version.");
                if (labels.TryGetValue(from[i], out var ids)) _copyLabels[to[i]] = ids;
            }
        }

        static void ConfigureCamera(Camera camera, CaptureOptions options, Scene scene)
        {
            camera.enabled = false; // renders only when Render() is called
            if (options.TemplateCamera != null)
            {
                camera.CopyFrom(options.TemplateCamera);
            }
            else
            {
                camera.fieldOfView = (float)options.VerticalFieldOfViewDegrees;
                camera.nearClipPlane = (float)options.NearClip;
                camera.farClipPlane = (float)options.FarClip;
                camera.cullingMask = ~0;
            }
            // Whatever the template says, these are what the dataset needs.
            camera.enabled = false;
            camera.usePhysicalProperties = false; // fieldOfView is then exactly the vertical FOV: no gate fit, no lens shift
            // A physical template's framing at W × H, reproduced by that plain vertical FOV (refused where it cannot be).
            if (options.WideVerticalFieldOfViewDegrees is double wide)
                // A lens capture's wide pinhole (Core LensCapture.WideRender): fieldOfView is the vertical FOV and the aspect
                // set below is W/H, so the render's focal is (H/2)/tan(fov/2) on both axes, centred — exactly the pinhole
                // Core resamples from (Documentation~/maintainers/lens-distortion.md, "The wide render in Unity").
                camera.fieldOfView = (float)wide;
            else if (options.TemplateCamera != null)
                camera.fieldOfView = (float)TemplateFraming.VerticalFieldOfView(options.TemplateCamera, options.Width, options.Height);
            // CopyFrom also brings the template's projection mode and viewport rect: an orthographic template or a
            // split-screen rect would render something other than the pinhole images the transforms describe.
            camera.orthographic = false;
            camera.rect = new Rect(0f, 0f, 1f, 1f);
            camera.allowDynamicResolution = false;
            // Review S3-7: a template's per-layer cull distances (if CopyFrom carries them; native) would drop far objects
            // from the colour pass while the data passes draw them. 0 = the far plane for every layer (UCR 2022.3
            // Runtime/Export/Camera/Camera.bindings.cs:97-103, 6000.0 :112-118). Spherical culling is Built-in only and
            // 6000's setter warns under a pipeline (:83-94), so it is reset only where it is on and there is none.
            camera.layerCullDistances = new float[32];
            if (camera.layerCullSpherical && UnityEngine.Rendering.GraphicsSettings.currentRenderPipeline == null) camera.layerCullSpherical = false;
            camera.ResetProjectionMatrix();
            camera.ResetWorldToCameraMatrix();
            camera.ResetCullingMatrix();
            camera.aspect = (float)options.Width / options.Height;
            camera.cameraType = CameraType.Game;
            camera.renderingPath = RenderingPath.Forward; // deferred loses alpha and needs MRT formats we do not own
            camera.clearFlags = CameraClearFlags.SolidColor;
            camera.backgroundColor = new Color(0f, 0f, 0f, 0f);
            if (options.Skybox != null)
            {
                // The sky of an environment capture. A Skybox component overrides the skybox its camera draws, in the
                // Built-in pipeline and URP (Manual: class-Skybox); URP 14 draws it for clear flags Skybox when the
                // camera has one even if RenderSettings.skybox is null (UniversalRenderer.cs:1106-1108), which the preview
                // scene's own lighting settings leave it. CopyFrom copies no components, so a template's is not here.
                camera.clearFlags = CameraClearFlags.Skybox;
                var sky = camera.GetComponent<Skybox>();
                if (sky == null) sky = camera.gameObject.AddComponent<Skybox>();
                sky.material = options.Skybox;
            }
            camera.allowHDR = false;
            camera.allowMSAA = false; // anti-aliasing is supersampling: MSAA would blend depth and normals
            camera.useOcclusionCulling = false;
            camera.depthTextureMode = DepthTextureMode.None;
            camera.targetTexture = null;
            camera.scene = scene;
            camera.transform.SetParent(null, false);
            camera.transform.localScale = Vector3.one;
        }

        public void Dispose()
        {
            UnpinLighting();
            if (Camera != null) Camera.targetTexture = null;
            // As PreviewRenderUtility does: close the scene (which destroys its objects), then make sure.
            if (_scene.IsValid()) EditorSceneManager.ClosePreviewScene(_scene);
            if (_root != null) Object.DestroyImmediate(_root);
            if (_cameraObject != null) Object.DestroyImmediate(_cameraObject);
            _dataPassRenderers.Clear();
            _copyLabels.Clear();
            Camera = null;
            _root = null;
            _cameraObject = null;
        }
    }
}
