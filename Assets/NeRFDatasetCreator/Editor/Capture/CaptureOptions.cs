using System.Collections.Generic;
using System.Globalization;
using UnityEngine;

namespace NerfDatasetCreator.Editor
{
    /// <summary>
    /// How to render the views of one capture: output size, supersampling, passes, lens and isolation. The lead's
    /// settings layer fills this from the user's Core settings; nothing here is persisted.
    /// </summary>
    public sealed class CaptureOptions
    {
        public const int MaxSize = 8192;
        /// <summary>Core's limit (<see cref="RawFrame.MaxSupersampling"/>): a larger k would render, then fail in the writer.</summary>
        public const int MaxSupersampling = RawFrame.MaxSupersampling;
        public const int MaxReadbacksInFlight = 8;

        /// <summary>Output image width in pixels (the written PNG's width, before supersampling).</summary>
        public int Width = 800;

        /// <summary>Output image height in pixels.</summary>
        public int Height = 800;

        /// <summary>k: colour and mask are rendered at k·W × k·H and box-filtered later (anti-aliased edges and alpha).</summary>
        public int Supersampling = 2;

        public CapturePasses Passes = CapturePasses.All;

        /// <summary>
        /// Vertical field of view in degrees, used unless <see cref="TemplateCamera"/> is set. Written to
        /// <c>Camera.fieldOfView</c> with physical properties off, so it is exactly the vertical FOV of the images.
        /// </summary>
        public double VerticalFieldOfViewDegrees = 39.6;

        /// <summary>
        /// A capture through a lens renders the wide pinhole of Core's <see cref="LensCapture.WideRender"/>: this vertical
        /// field of view (degrees) replaces <see cref="VerticalFieldOfViewDegrees"/> and the template camera's, and
        /// <see cref="Width"/> × <see cref="Height"/> are the wide render's size. Null without a lens.
        /// </summary>
        public double? WideVerticalFieldOfViewDegrees;

        public double NearClip = 0.05;
        public double FarClip = 1000.0;

        /// <summary>
        /// Optional user camera to copy settings from (field of view, clip planes, culling mask, via <c>Camera.CopyFrom</c>).
        /// Everything the dataset depends on (aspect, clear colour, HDR, MSAA, physical properties…) is re-applied after.
        /// </summary>
        public Camera TemplateCamera;

        public CaptureIsolation Isolation = CaptureIsolation.TargetOnly;

        /// <summary>
        /// Environment capture: the skybox material drawn behind everything (clear flags Skybox, through a Skybox
        /// component on the capture camera); null for the difference-matting clears over black and white. With a sky
        /// the colour pass renders once and that image is both halves of the matting pair, so alpha is 255 everywhere.
        /// </summary>
        public Material Skybox;

        /// <summary>TargetOnly mode: bring copies of the scene's enabled lights into the preview scene (else it is unlit but for ambient).</summary>
        public bool CopySceneLights = true;

        /// <summary>Views whose GPU readback may be pending at once; each holds its own set of render textures.</summary>
        public int ReadbacksInFlight = 3;

        /// <summary>
        /// Render depth and normals at the output size (one sample exactly at each pixel centre, k² less memory) instead
        /// of the supersampled size. Depth and normals must never be averaged, so nothing is lost.
        /// </summary>
        public bool DepthAndNormalAtOutputSize = true;

        /// <summary>Use ReadPixels even where AsyncGPUReadback is supported (diagnostics; the slower, always-available path).</summary>
        public bool ForceSynchronousReadback;

        /// <summary>
        /// Called before each view is rendered with the root of the capture's copies and the view's index (a dynamic
        /// capture poses its content there at the view's time, see ContentClock); null for a static capture.
        /// </summary>
        public System.Action<GameObject, int> BeforeView;

        /// <summary>
        /// The instance and class ids of the scene's renderers (the user's objects, not the capture's copies): with it the
        /// capture draws the labels pass (<see cref="CapturePasses.Labels"/>), each copy with its source's ids. Null: no
        /// labels pass. Filled by <c>SceneLabels</c> from Core's label table.
        /// </summary>
        public IReadOnlyDictionary<Renderer, RendererLabelIds> Labels;

        /// <summary>
        /// Motion blur: the sub-frames of view i (Core's <see cref="SubFrameSchedule"/>), rendered and averaged in linear
        /// light before the view's own mid-pose render, which then gives the sharp image and the data passes; null (or a
        /// null list) renders the view sharp only.
        /// </summary>
        public System.Func<int, System.Collections.Generic.IReadOnlyList<SubFrame>> SubFramesOf;

        /// <summary>Motion blur: the rolling shutter's readout (<see cref="RollingShutter"/>); 0 for a global shutter.</summary>
        public double RollingShutterReadout;

        /// <summary>
        /// Motion blur: called before each sub-frame is rendered, after the camera (whose transform is passed) is posed,
        /// with the root of the capture's copies: a dynamic capture poses its content at the sub-frame's time here.
        /// </summary>
        public System.Action<GameObject, SubFrame, Transform> BeforeSubFrame;

        /// <summary>
        /// Material passes (issue 38) rendered per view at the colour's supersampled size (<see cref="MaterialPassCapture"/>);
        /// null or empty: none.
        /// </summary>
        public IReadOnlyList<MaterialPassKind> MaterialPasses;

        /// <summary>
        /// Relighting (issue 38): one more colour pair per view for each of these renders (<see cref="RelitColourRenderer"/>),
        /// from Core's <see cref="RelightingInUnity.Resolve"/>; null or empty: none.
        /// </summary>
        public IReadOnlyList<UnityLightingRender> Relighting;

        public int SupersampledWidth => Width * Supersampling;
        public int SupersampledHeight => Height * Supersampling;
        public int DataWidth => DepthAndNormalAtOutputSize ? Width : SupersampledWidth;
        public int DataHeight => DepthAndNormalAtOutputSize ? Height : SupersampledHeight;

        /// <summary>Every problem with these options at once, each naming the field, its value and the fix.</summary>
        public List<ValidationProblem> Validate()
        {
            var problems = new List<ValidationProblem>
            {
                ValidationProblem.OutsideRange("capture.width", Width, 1, MaxSize),
                ValidationProblem.OutsideRange("capture.height", Height, 1, MaxSize),
                ValidationProblem.OutsideRange("capture.supersampling", Supersampling, 1, MaxSupersampling),
                ValidationProblem.OutsideRange("capture.readbacksInFlight", ReadbacksInFlight, 1, MaxReadbacksInFlight),
            };
            if (WideVerticalFieldOfViewDegrees is double wide)
                // The template's framing was checked at the output size; the wide render has its own field of view.
                problems.Add(ValidationProblem.OutsideRange("capture.wideVerticalFieldOfViewDegrees", wide, 0.01, LensPinholeCover.MaxFovDegrees, "degrees"));
            else if (TemplateCamera != null)
                problems.Add(TemplateFraming.Problem(TemplateCamera, Width, Height, TemplateCamera.name));
            else
            {
                problems.Add(ValidationProblem.OutsideRange("capture.verticalFieldOfViewDegrees", VerticalFieldOfViewDegrees, 0.01, 179.0, "degrees"));
                problems.Add(ValidationProblem.OutsideRange("capture.nearClip", NearClip, 1e-5, 1e6));
                if (!(FarClip > NearClip) || double.IsInfinity(FarClip))
                    problems.Add(new ValidationProblem("capture.farClip", ValidationProblem.Format(FarClip),
                        "must be a finite distance beyond the near clip plane (" + ValidationProblem.Format(NearClip) + ").",
                        "Use a far clip larger than the near clip that encloses the target from every camera."));
            }
            if (Width > 0 && Supersampling > 0 && (long)Width * Supersampling > 16384)
                problems.Add(new ValidationProblem("capture.supersampling",
                    Supersampling.ToString(CultureInfo.InvariantCulture),
                    "makes the rendered width " + ((long)Width * Supersampling).ToString(CultureInfo.InvariantCulture) + " pixels, beyond the 16384 GPUs support.",
                    "Lower the supersampling or the resolution."));
            if (Height > 0 && Supersampling > 0 && (long)Height * Supersampling > 16384)
                problems.Add(new ValidationProblem("capture.supersampling",
                    Supersampling.ToString(CultureInfo.InvariantCulture),
                    "makes the rendered height " + ((long)Height * Supersampling).ToString(CultureInfo.InvariantCulture) + " pixels, beyond the 16384 GPUs support.",
                    "Lower the supersampling or the resolution."));
            if (Passes == CapturePasses.None)
                problems.Add(new ValidationProblem("capture.passes", "None", "renders nothing.", "Choose at least the colour pass."));
            problems.RemoveAll(p => p == null);
            return problems;
        }

        /// <summary>Throws <see cref="InvalidParameterException"/> listing every problem, if any.</summary>
        public void ThrowIfInvalid() => InvalidParameterException.ThrowIfAny(Validate().ToArray());

        /// <summary>
        /// The passes rendered. Colour no longer needs the mask: its alpha comes from rendering it over black and over
        /// white (difference matting), so the mask pass runs only when mask images are asked for. The labels pass runs
        /// exactly when <see cref="Labels"/> is given.
        /// </summary>
        public CapturePasses EffectivePasses => Labels != null ? Passes | CapturePasses.Labels : Passes & ~CapturePasses.Labels;
    }
}
