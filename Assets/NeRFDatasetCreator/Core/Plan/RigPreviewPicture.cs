using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// <c>rig_preview.png</c>: the planned cameras drawn from above and from the front, so a rig can be checked
    /// without MeshLab. Both panels are orthographic views of the output (Blender) frame at one shared scale —
    /// the top view with X right and Y up (looking down −Z), the side view with X right and Z up (looking along +Y,
    /// Blender's front view) — centred on the target. Each camera is a disc in its split's colour
    /// (<see cref="SplitColors"/>, as the Scene-view preview and <see cref="RigPreviewPly"/>) with a tick along its
    /// viewing direction; nearer cameras are drawn over farther ones. The target is a white cross with its bounding
    /// sphere when known, the formation's distance sphere a dotted circle; grid lines are <see cref="GridStep"/>
    /// apart (its value is printed in the legend). A split that samples an inside-out volume draws its box instead
    /// of the target's sphere: the twelve edges of the oriented box, projected into each panel in the split's colour
    /// (their outer edges are the outline of the box's projection).
    /// </summary>
    public static class RigPreviewPicture
    {
        public const string FileName = "rig_preview.png";

        /// <summary>Side of each square panel in pixels.</summary>
        public const int PanelSize = 480;

        /// <summary>Space around and between the panels.</summary>
        public const int Gap = 16;

        /// <summary>Height of the title strip above the panels and of the legend strip below them.</summary>
        public const int HeaderHeight = 28;
        public const int FooterHeight = 32;

        /// <summary>Pixels kept free between the farthest drawn point and the panel's edge.</summary>
        public const int Margin = 24;

        /// <summary>Length of a camera's viewing-direction tick for a direction in the panel's plane, and its disc's radius.</summary>
        public const double TickLength = 16;
        public const double DiscRadius = 3.5;

        public const int Width = Gap + PanelSize + Gap + PanelSize + Gap;
        public const int Height = HeaderHeight + PanelSize + FooterHeight;

        public static readonly byte[] Background = { 20, 20, 20 };
        public static readonly byte[] PanelBackground = { 36, 36, 36 };
        public static readonly byte[] GridColour = { 52, 52, 52 };
        public static readonly byte[] AxisColour = { 84, 84, 84 };
        public static readonly byte[] TargetFill = { 72, 72, 72 };
        public static readonly byte[] TextColour = { 220, 220, 220 };

        /// <summary>Left edge of the top view's panel, then the side view's; both panels start at <see cref="HeaderHeight"/>.</summary>
        public const int TopPanelLeft = Gap;
        public const int SidePanelLeft = Gap + PanelSize + Gap;

        /// <summary>The picture of a plan as PNG bytes (8-bit RGB).</summary>
        public static byte[] Encode(CapturePlan plan)
        {
            var canvas = Draw(plan);
            return PngWriter.Encode(canvas.Pixels, canvas.Width, canvas.Height, PngPixelFormat.Rgb8);
        }

        public static RgbCanvas Draw(CapturePlan plan)
        {
            if (plan == null) throw new ArgumentNullException(nameof(plan));
            var scale = plan.Normalisation.Scale;
            var boxes = VolumeBoxes(plan);
            // An environment's "target" is its root object: its sphere would cover the picture, the box says more.
            var targetRadius = plan.Target.HasBounds && boxes.Count == 0 ? plan.Target.BoundingRadius * scale : 0;
            var sphereRadius = CameraSourcePlanning.AnyFormation(plan.Settings) ? plan.Distance * scale : 0;
            return Draw(new PlanCameras(plan.Views),
                plan.Normalisation.ApplyToUnityPoint(plan.Target.Centre), targetRadius, sphereRadius, boxes);
        }

        /// <summary>The box of every split with views that samples an inside-out volume, in the plan's output frame.</summary>
        public static IReadOnlyList<PictureBox> VolumeBoxes(CapturePlan plan) =>
            VolumePlanning.Boxes(plan).Select(b => PictureBox.FromUnity(b.Key, b.Value, plan.Normalisation)).ToList();

        /// <summary>
        /// Draws cameras (output camera-to-world matrices) around a target centre (output frame) with its bounding
        /// sphere's radius and the formation sphere's radius (0 for none), and the volume boxes (none for null).
        /// </summary>
        public static RgbCanvas Draw(IReadOnlyList<PictureCamera> cameras, Vector3d target, double targetRadius, double sphereRadius,
            IReadOnlyList<PictureBox> boxes = null)
        {
            boxes = boxes ?? Array.Empty<PictureBox>();
            var extent = Math.Max(targetRadius, sphereRadius);
            var counts = new int[DatasetSplits.All.Count]; // for the legend, in the same pass: a plan's cameras are made as they are read
            foreach (var c in cameras)
            {
                extent = Math.Max(extent, Reach(c.CameraToWorld.Translation - target));
                counts[(int)c.Split]++;
            }
            foreach (var b in boxes)
                foreach (var corner in b.Corners) extent = Math.Max(extent, Reach(corner - target));
            if (!(extent > 0) || double.IsInfinity(extent)) extent = 1;
            var pixelsPerUnit = (PanelSize / 2.0 - Margin) / extent;
            var grid = GridStep(extent);

            var canvas = new RgbCanvas(Width, Height, Background);
            foreach (var panel in new[] { Panel.Top, Panel.Side })
                DrawPanel(canvas, panel, boxes, target, targetRadius, sphereRadius, pixelsPerUnit, grid);
            DrawCameras(canvas, cameras, target, pixelsPerUnit);
            canvas.Text(TopPanelLeft, 7, "TOP: X RIGHT, Y UP", TextColour);
            canvas.Text(SidePanelLeft, 7, "SIDE: X RIGHT, Z UP", TextColour);
            DrawLegend(canvas, counts, grid, boxes.Count > 0);
            return canvas;
        }

        static double Reach(Vector3d d) => Math.Max(Math.Abs(d.X), Math.Max(Math.Abs(d.Y), Math.Abs(d.Z)));

        /// <summary>The panel pixel (continuous: pixel i spans [i, i + 1)) of an output-frame point in the top view.</summary>
        public static double[] TopPixel(Vector3d point, Vector3d target, double pixelsPerUnit) => ToPixel(Panel.Top, point, target, pixelsPerUnit);

        /// <summary>The same in the side view.</summary>
        public static double[] SidePixel(Vector3d point, Vector3d target, double pixelsPerUnit) => ToPixel(Panel.Side, point, target, pixelsPerUnit);

        /// <summary>The grid spacing for a half-width of <paramref name="extent"/>: 1, 2 or 5 × 10ⁿ, two to five lines each side.</summary>
        public static double GridStep(double extent)
        {
            var raw = extent / 4;
            var power = Math.Pow(10, Math.Floor(Math.Log10(raw)));
            foreach (var m in new[] { 1.0, 2.0, 5.0, 10.0 })
                if (m * power >= raw) return m * power;
            return 10 * power;
        }

        enum Panel { Top, Side }

        static readonly Panel[] Panels = { Panel.Top, Panel.Side };

        static double[] ToPixel(Panel panel, Vector3d p, Vector3d target, double pixelsPerUnit)
        {
            var d = p - target;
            var left = panel == Panel.Top ? TopPanelLeft : SidePanelLeft;
            var up = panel == Panel.Top ? d.Y : d.Z;
            return new[] { left + PanelSize / 2.0 + d.X * pixelsPerUnit, HeaderHeight + PanelSize / 2.0 - up * pixelsPerUnit };
        }

        /// <summary>A panel's background, grid, target, formation sphere and boxes: everything under the cameras.</summary>
        static void DrawPanel(RgbCanvas canvas, Panel panel, IReadOnlyList<PictureBox> boxes, Vector3d target,
            double targetRadius, double sphereRadius, double pixelsPerUnit, double grid)
        {
            var left = panel == Panel.Top ? TopPanelLeft : SidePanelLeft;
            canvas.FillRect(left, HeaderHeight, PanelSize, PanelSize, PanelBackground);
            canvas.Clip(left, HeaderHeight, left + PanelSize, HeaderHeight + PanelSize);
            var cx = left + PanelSize / 2.0;
            var cy = HeaderHeight + PanelSize / 2.0;
            var lines = (int)Math.Ceiling(PanelSize / 2.0 / (grid * pixelsPerUnit));
            for (var k = -lines; k <= lines; k++)
            {
                var colour = k == 0 ? AxisColour : GridColour;
                var o = k * grid * pixelsPerUnit;
                canvas.Line(cx + o, HeaderHeight, cx + o, HeaderHeight + PanelSize, colour);
                canvas.Line(left, cy + o, left + PanelSize, cy + o, colour);
            }
            if (targetRadius > 0)
            {
                canvas.FillDisc(cx, cy, targetRadius * pixelsPerUnit, TargetFill);
                canvas.Circle(cx, cy, targetRadius * pixelsPerUnit, TextColour);
            }
            if (sphereRadius > 0) canvas.Circle(cx, cy, sphereRadius * pixelsPerUnit, Byte3(SplitColors.Guides), dash: 4);
            foreach (var box in boxes)
            {
                var colour = Byte3(SplitColors.Of(ToPreview(box.Split)));
                foreach (var (a, b) in PictureBox.Edges)
                {
                    var p = ToPixel(panel, box.Corners[a], target, pixelsPerUnit);
                    var q = ToPixel(panel, box.Corners[b], target, pixelsPerUnit);
                    canvas.Line(p[0], p[1], q[0], q[1], colour);
                }
            }
            canvas.Line(cx - 6, cy, cx + 6, cy, TextColour);
            canvas.Line(cx, cy - 6, cx, cy + 6, TextColour);

            canvas.ResetClip();
        }

        /// <summary>
        /// The cameras in both panels, in one pass over them (a plan makes them as they are read). Painter's order: the
        /// viewer of the top view is above (+Z), of the side view in front (−Y); farthest first, equal depths in list
        /// order. Each panel's <see cref="PaintersBuffer"/> keeps, per pixel, what that order would have drawn last, so
        /// no sorted copy of the cameras is made. The panels do not overlap, so drawing them together changes nothing.
        /// </summary>
        static void DrawCameras(RgbCanvas canvas, IReadOnlyList<PictureCamera> cameras, Vector3d target, double pixelsPerUnit)
        {
            var top = new PaintersBuffer(TopPanelLeft, HeaderHeight, PanelSize, PanelSize, descending: false);
            var side = new PaintersBuffer(SidePanelLeft, HeaderHeight, PanelSize, PanelSize, descending: true);
            var index = 0;
            foreach (var c in cameras)
            {
                var colour = Byte3(SplitColors.Of(ToPreview(c.Split)));
                var t = c.CameraToWorld.Translation;
                // An OpenGL camera looks along its −Z column; the tick shows that direction's share in the panel's plane.
                var look = (-c.CameraToWorld.Column(2)).Normalized();
                foreach (var panel in Panels)
                {
                    var left = panel == Panel.Top ? TopPanelLeft : SidePanelLeft;
                    var painter = panel == Panel.Top ? top : side;
                    canvas.Clip(left, HeaderHeight, left + PanelSize, HeaderHeight + PanelSize);
                    canvas.Filter = painter.Accept;
                    var at = ToPixel(panel, t, target, pixelsPerUnit);
                    var up = panel == Panel.Top ? look.Y : look.Z;
                    var depth = panel == Panel.Top ? t.Z : t.Y;
                    painter.Item(depth, index, 0);
                    canvas.Line(at[0], at[1], at[0] + look.X * TickLength, at[1] - up * TickLength, colour);
                    painter.Item(depth, index, 1);
                    canvas.FillDisc(at[0], at[1], DiscRadius, colour);
                }
                index++;
            }
            canvas.Filter = null;
            canvas.ResetClip();
        }

        /// <summary>A plan's views as pictured cameras, made as they are read (a copy of 300 000 would be 41 MB).</summary>
        sealed class PlanCameras : IReadOnlyList<PictureCamera>
        {
            readonly IReadOnlyList<PlannedView> _views;

            public PlanCameras(IReadOnlyList<PlannedView> views) => _views = views;

            public int Count => _views.Count;

            public PictureCamera this[int index]
            {
                get
                {
                    var view = _views[index]; // made on each read (PlannedViewList): once here
                    return new PictureCamera(view.Split, view.TransformMatrix);
                }
            }

            public IEnumerator<PictureCamera> GetEnumerator()
            {
                for (var i = 0; i < _views.Count; i++) yield return this[i];
            }

            System.Collections.IEnumerator System.Collections.IEnumerable.GetEnumerator() => GetEnumerator();
        }

        static void DrawLegend(RgbCanvas canvas, int[] counts, double grid, bool boxes)
        {
            var x = TopPanelLeft;
            var y = HeaderHeight + PanelSize + 10;
            foreach (var split in DatasetSplits.All)
            {
                canvas.FillDisc(x + 5, y + 7, 5, Byte3(SplitColors.Of(ToPreview(split))));
                x += 16;
                x += canvas.Text(x, y, DatasetSplits.Name(split) + " " + counts[(int)split].ToString(CultureInfo.InvariantCulture), TextColour) + 24;
            }
            canvas.Text(x, y, "GRID " + grid.ToString("G4", CultureInfo.InvariantCulture) + "   + TARGET" + (boxes ? "   BOX: VOLUME" : ""), TextColour);
        }

        static PreviewSplit ToPreview(DatasetSplit split) =>
            split == DatasetSplit.Train ? PreviewSplit.Train : split == DatasetSplit.Val ? PreviewSplit.Val : PreviewSplit.Test;

        /// <summary>8-bit components of a palette colour, as <see cref="RigPreviewPly"/> rounds them.</summary>
        public static byte[] Byte3(RgbaColor c) => new[] { ToByte(c.R), ToByte(c.G), ToByte(c.B) };

        static byte ToByte(float component) => (byte)Math.Round(Math.Max(0, Math.Min(1, component)) * 255);
    }

    /// <summary>An inside-out volume's box in the rig picture: its split and its eight corners in the output frame.</summary>
    public sealed class PictureBox
    {
        /// <summary>Corner i is at box coordinates (±½, ±½, ±½), bit 0 of i choosing x, bit 1 y, bit 2 z.</summary>
        public PictureBox(DatasetSplit split, IReadOnlyList<Vector3d> corners)
        {
            if (corners == null || corners.Count != 8) throw new ArgumentException("A box has eight corners.", nameof(corners));
            Split = split;
            Corners = corners;
        }

        /// <summary>The twelve edges: the corner pairs that differ in one coordinate.</summary>
        public static readonly (int, int)[] Edges = BuildEdges();

        /// <summary>A Unity-world box (<see cref="OrientedBox"/>) moved into the output frame by a normalisation.</summary>
        public static PictureBox FromUnity(DatasetSplit split, OrientedBox box, SceneNormalisation normalisation)
        {
            var corners = new Vector3d[8];
            for (var i = 0; i < 8; i++)
                corners[i] = normalisation.ApplyToUnityPoint(box.PointAt(new Vector3d((i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5)));
            return new PictureBox(split, corners);
        }

        public DatasetSplit Split { get; }
        public IReadOnlyList<Vector3d> Corners { get; }

        static (int, int)[] BuildEdges()
        {
            var edges = new List<(int, int)>();
            for (var i = 0; i < 8; i++)
                for (var bit = 1; bit < 8; bit <<= 1)
                    if ((i & bit) == 0) edges.Add((i, i | bit));
            return edges.ToArray();
        }
    }

    /// <summary>A camera of the rig picture: its split and output camera-to-world matrix.</summary>
    public readonly struct PictureCamera
    {
        public PictureCamera(DatasetSplit split, Matrix4x4d cameraToWorld)
        {
            Split = split;
            CameraToWorld = cameraToWorld;
        }

        public DatasetSplit Split { get; }
        public Matrix4x4d CameraToWorld { get; }
    }
}
