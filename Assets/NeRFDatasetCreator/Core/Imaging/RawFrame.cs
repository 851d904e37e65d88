using System.Collections.Generic;
using System.Globalization;

namespace NerfDatasetCreator
{
    /// <summary>
    /// One view as the Unity capture layer reads it back, before any pixel processing: every array holds Width×Height
    /// pixels of the supersampled render textures, rows bottom-up (row 0 is the bottom of the image, as
    /// ReadPixels / AsyncGPUReadback deliver them), pixels left to right, channels interleaved. Set only the
    /// passes that were rendered. The exact meaning of every array is in Documentation~/pixels.md.
    /// </summary>
    public sealed class RawFrame
    {
        public RawFrame(int width, int height, int supersampling)
        {
            Width = width;
            Height = height;
            Supersampling = supersampling;
        }

        public const int MaxSupersampling = 4;

        /// <summary>Width of the render textures (output width × <see cref="Supersampling"/>).</summary>
        public int Width { get; }

        /// <summary>Height of the render textures (output height × <see cref="Supersampling"/>).</summary>
        public int Height { get; }

        /// <summary>k: each output pixel is a k×k block of rendered samples, k = 1…4.</summary>
        public int Supersampling { get; }

        public int OutputWidth => Width / Supersampling;
        public int OutputHeight => Height / Supersampling;

        /// <summary>
        /// Colour as read back from an <c>R8G8B8A8_SRGB</c> render texture (Linear colour-space project) or an
        /// <c>R8G8B8A8_UNorm</c> one (Gamma project): 4 bytes per pixel, R G B A, sRGB-encoded, rendered over a
        /// (0,0,0,0) clear. The A byte is ignored. Set this or <see cref="ColorLinear"/>.
        /// </summary>
        public byte[] ColorSrgb { get; set; }

        /// <summary>
        /// Colour as linear floats, 4 per pixel (R G B A), from an <c>R32G32B32A32_SFloat</c> render texture or an
        /// <c>R16G16B16A16_SFloat</c> one read back into floats; rendered over a (0,0,0,0) clear. A is ignored;
        /// values above 1 are clamped after un-premultiplying.
        /// </summary>
        public float[] ColorLinear { get; set; }

        /// <summary>
        /// The colour pass rendered over a <b>black</b> clear into an <c>R16G16B16A16_SFloat</c> texture: 4 IEEE halves
        /// per pixel (R G B A, A ignored), the values the shaders wrote (linear light in a Linear project, gamma-space
        /// in a Gamma one: see <see cref="ColorIsGammaEncoded"/>). With <see cref="ColorOverWhite"/>, the input of
        /// <see cref="DifferenceMatting"/>, which solves alpha and straight colour from the pair.
        /// </summary>
        public ushort[] ColorOverBlack { get; set; }

        /// <summary>The same view's colour pass rendered over a <b>white</b> (1, 1, 1) clear; same format as <see cref="ColorOverBlack"/>.</summary>
        public ushort[] ColorOverWhite { get; set; }

        /// <summary>
        /// True when the colour pair comes from a Gamma colour-space project: the shaders wrote, and the GPU blended,
        /// gamma-space (sRGB-curve) values. False (Linear project): linear light.
        /// </summary>
        public bool ColorIsGammaEncoded { get; set; }

        /// <summary>
        /// Coverage from the mask pass: 255 where the target covers the sample, 0 elsewhere (intermediate values are
        /// fractional coverage). <see cref="MaskBytesPerPixel"/> bytes per pixel with coverage in the first byte.
        /// </summary>
        public byte[] Mask { get; set; }

        /// <summary>4 for an <c>R8G8B8A8_UNorm</c> mask texture (coverage in R), 1 for <c>R8_UNorm</c>.</summary>
        public int MaskBytesPerPixel { get; set; } = 4;

        /// <summary>
        /// Eye z-depth in metres, one float per pixel (<c>R32_SFloat</c>): the distance along the camera's forward
        /// axis, positive in front of the camera; 0 (the clear value) where no surface was hit.
        /// </summary>
        public float[] Depth { get; set; }

        /// <summary>
        /// Unit normals, <see cref="NormalFloatsPerPixel"/> floats per pixel (x y z [w]), in the frame the dataset
        /// uses (see pixels.md) — or in Unity's world frame when <see cref="NormalsInUnityWorld"/> is set; (0,0,0)
        /// (the clear value) where no surface was hit.
        /// </summary>
        public float[] Normals { get; set; }

        /// <summary>
        /// The normals are Unity world normals, as the normal pass renders them: the encoders relabel them into the
        /// output world (<see cref="BlenderConvention.FromUnity"/>: y and z swap) as they read them, which gives the
        /// same bits as <see cref="NormalFrames.ToOutputWorld"/> first, without a pass of its own.
        /// </summary>
        public bool NormalsInUnityWorld { get; set; }

        /// <summary>4 for an <c>R16G16B16A16_SFloat</c>/<c>R32G32B32A32_SFloat</c> normal texture (w ignored), 3 for packed xyz.</summary>
        public int NormalFloatsPerPixel { get; set; } = 4;

        /// <summary>
        /// Instance ids from the id pass, one per sample (<c>R16_UInt</c>, or an id packed in two bytes of an RGBA8 texture
        /// and unpacked by the Unity layer): the <see cref="LabelTable"/> id of the object that covers the sample, 0 (the
        /// clear value) where none does. Rendered with the mask pass's cull and alpha-clip rules; never filtered or blended.
        /// <see cref="IdMajority"/> turns a k×k block into one output pixel (Documentation~/labels.md).
        /// </summary>
        public ushort[] InstanceIds { get; set; }

        /// <summary>
        /// Material pass (issue 38): the shader's base colour (albedo), linear, 4 floats per sample (R G B, A ignored),
        /// drawn unlit with no post-processing over a (0,0,0,0) clear; coverage comes from <see cref="Mask"/>.
        /// </summary>
        public float[] MaterialAlbedo { get; set; }

        /// <summary>Material pass: metallic in [0, 1], one float per sample; 0 where nothing is drawn.</summary>
        public float[] MaterialMetallic { get; set; }

        /// <summary>Material pass: perceptual roughness = 1 − smoothness in [0, 1], one float per sample.</summary>
        public float[] MaterialRoughness { get; set; }

        /// <summary>Material pass: specular colour (specular-setup shaders), linear, 4 floats per sample (A ignored).</summary>
        public float[] MaterialSpecular { get; set; }

        /// <summary>Material pass: emission, linear (may exceed 1), 4 floats per sample (A ignored).</summary>
        public float[] MaterialEmission { get; set; }

        /// <summary>
        /// Material coverage: 255 where the sample's shader is one whose parameters the material passes read exactly,
        /// 0 where it is another shader (its values are not guessed) or nothing is drawn; one byte per sample.
        /// </summary>
        public byte[] MaterialSupported { get; set; }

        /// <summary>
        /// Relighting (issue 38): the colour of this view under each extra lighting condition, keyed by the file-name
        /// key of the condition and rotation (<c>sunset_090</c>, <c>olat-03</c>); each value carries only the colour
        /// arrays (<see cref="ColorSrgb"/>, <see cref="ColorLinear"/> or the over-black/over-white pair) and goes through
        /// the same colour pipeline as this frame.
        /// </summary>
        public Dictionary<string, RawFrame> Relit { get; set; }

        /// <summary>Every problem with the sizes and arrays at once; empty when the frame is usable.</summary>
        public List<ValidationProblem> Validate()
        {
            var problems = new List<ValidationProblem>();
            void Add(ValidationProblem p) { if (p != null) problems.Add(p); }

            Add(ValidationProblem.OutsideRange("frame.Supersampling", Supersampling, 1, MaxSupersampling));
            Add(ValidationProblem.OutsideRange("frame.Width", Width, 1, CameraIntrinsics.MaxSize * MaxSupersampling));
            Add(ValidationProblem.OutsideRange("frame.Height", Height, 1, CameraIntrinsics.MaxSize * MaxSupersampling));
            if (problems.Count > 0) return problems;

            int k = Supersampling;
            if (Width % k != 0)
                problems.Add(new ValidationProblem("frame.Width", Text(Width), $"is not a multiple of the supersampling factor {Text(k)}.",
                    $"Render at {Text(k)}× the output width, e.g. {Text(Width / k * k)}."));
            if (Height % k != 0)
                problems.Add(new ValidationProblem("frame.Height", Text(Height), $"is not a multiple of the supersampling factor {Text(k)}.",
                    $"Render at {Text(k)}× the output height, e.g. {Text(Height / k * k)}."));
            if (MaskBytesPerPixel != 1 && MaskBytesPerPixel != 4)
                problems.Add(new ValidationProblem("frame.MaskBytesPerPixel", Text(MaskBytesPerPixel), "must be 1 (R8_UNorm) or 4 (R8G8B8A8_UNorm).", "Use 4 for an RGBA8 mask texture."));
            if (NormalFloatsPerPixel != 3 && NormalFloatsPerPixel != 4)
                problems.Add(new ValidationProblem("frame.NormalFloatsPerPixel", Text(NormalFloatsPerPixel), "must be 3 (xyz) or 4 (xyzw).", "Use 4 for an RGBA float normal texture."));
            if (ColorSrgb != null && ColorLinear != null)
                problems.Add(new ValidationProblem("frame.ColorSrgb", "set", "and frame.ColorLinear are both set; the colour pass has one format.", "Set only the array matching the render texture format."));
            if ((ColorOverBlack == null) != (ColorOverWhite == null))
                problems.Add(new ValidationProblem(ColorOverBlack == null ? "frame.ColorOverBlack" : "frame.ColorOverWhite", "null",
                    "is missing: difference matting needs the colour pass over black and over white.", "Read back both colour renders."));
            if (ColorOverBlack != null && (ColorSrgb != null || ColorLinear != null))
                problems.Add(new ValidationProblem("frame.ColorOverBlack", "set", "and frame.ColorSrgb/ColorLinear are both set; a frame has one colour representation.",
                    "Set the matting pair or a single colour array, not both."));

            long pixels = (long)Width * Height;
            CheckLength(problems, "frame.ColorSrgb", ColorSrgb?.Length, pixels * 4, "4 bytes (RGBA) per pixel");
            CheckLength(problems, "frame.ColorLinear", ColorLinear?.Length, pixels * 4, "4 floats (RGBA) per pixel");
            CheckLength(problems, "frame.ColorOverBlack", ColorOverBlack?.Length, pixels * 4, "4 halves (RGBA) per pixel");
            CheckLength(problems, "frame.ColorOverWhite", ColorOverWhite?.Length, pixels * 4, "4 halves (RGBA) per pixel");
            CheckLength(problems, "frame.Mask", Mask?.Length, pixels * MaskBytesPerPixel, $"{Text(MaskBytesPerPixel)} byte(s) per pixel");
            CheckLength(problems, "frame.Depth", Depth?.Length, pixels, "1 float per pixel");
            CheckLength(problems, "frame.InstanceIds", InstanceIds?.Length, pixels, "1 id (ushort) per pixel");
            CheckLength(problems, "frame.Normals", Normals?.Length, pixels * NormalFloatsPerPixel, $"{Text(NormalFloatsPerPixel)} floats per pixel");
            return problems;
        }

        /// <summary>Throws <see cref="InvalidParameterException"/> unless the frame is valid and has every named pass.</summary>
        internal void Require(bool color, bool mask, bool depth, bool normals)
        {
            var problems = Validate();
            if (color && ColorSrgb == null && ColorLinear == null) problems.Add(Missing("frame.ColorSrgb", "the colour pass (or frame.ColorLinear)"));
            if (mask && Mask == null) problems.Add(Missing("frame.Mask", "the mask pass"));
            if (depth && Depth == null) problems.Add(Missing("frame.Depth", "the depth pass"));
            if (normals && Normals == null) problems.Add(Missing("frame.Normals", "the normal pass"));
            if (problems.Count > 0) throw new InvalidParameterException(problems);
        }

        internal static void RequireOutput(string field, System.Array output, long expected, string unit)
        {
            if (output == null || output.Length < expected)
                throw new InvalidParameterException(new[]
                {
                    new ValidationProblem(field, output == null ? "null" : $"length {Text(output.Length)}", $"is too small: the output needs {expected.ToString(CultureInfo.InvariantCulture)} {unit}.",
                        "Allocate (or rent) an array of at least that length.")
                });
        }

        static ValidationProblem Missing(string field, string what) =>
            new ValidationProblem(field, "null", $"is required: this step reads {what}.", "Read the pass back into this array first.");

        static void CheckLength(List<ValidationProblem> problems, string field, int? actual, long expected, string layout)
        {
            if (actual == null || actual.Value == expected) return;
            problems.Add(new ValidationProblem(field, $"length {Text(actual.Value)}",
                $"does not match {layout} at the frame size (expected {expected.ToString(CultureInfo.InvariantCulture)}).",
                "Pass the readback of a render texture of frame.Width × frame.Height in the documented format."));
        }

        static string Text(int value) => value.ToString(CultureInfo.InvariantCulture);
    }
}
