using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;

namespace NerfDatasetCreator
{
    /// <summary>
    /// The capture's label files besides the per-view maps: <c>labels.json</c> and one <c>labels_preview_&lt;split&gt;.png</c>
    /// per split with views, made from the instance maps the capture has just written into the working folder.
    /// </summary>
    public static class LabelFiles
    {
        /// <summary>Writes labels.json and the previews of <paramref name="plan"/>'s splits (the views this run wrote).</summary>
        public static void Write(DatasetWriteSession session, CapturePlan plan, LabelTable table)
        {
            if (session == null) throw new ArgumentNullException(nameof(session));
            if (plan == null) throw new ArgumentNullException(nameof(plan));
            if (table == null) throw new ArgumentNullException(nameof(table));
            session.WriteText(DatasetLayout.LabelsFileName, LabelsJson.Write(table));
            foreach (var split in DatasetSplits.All)
            {
                var views = plan.Views.Where(v => v.Split == split && v.Writes(DatasetFileKind.InstancePng))
                    .OrderBy(v => v.Index).Take(LabelPreview.MaxViews).ToList();
                if (views.Count == 0) continue;
                var maps = new List<ushort[]>();
                int width = 0, height = 0;
                foreach (var view in views)
                {
                    var path = session.PathOf(DatasetLayout.RelativePath(view.Split, view.Index, DatasetFileKind.InstancePng));
                    if (!File.Exists(path)) continue; // a view this run did not get to (a stopped capture writes no previews of it)
                    var map = PngGray16Reader.Read(path, out var w, out var h, "instance map");
                    if (maps.Count == 0)
                    {
                        width = w;
                        height = h;
                    }
                    if (w == width && h == height) maps.Add(map);
                }
                if (maps.Count == 0) continue;
                var png = LabelPreview.Encode(maps, width, height);
                session.WriteBytes(DatasetLayout.LabelsPreviewFileName(DatasetSplits.Name(split)), s => s.Write(png, 0, png.Length));
            }
        }

        /// <summary>
        /// Writes the previews of a finished dataset folder from its split folders' instance maps (the first
        /// <see cref="LabelPreview.MaxViews"/> by view index): merge makes them anew for the merged splits.
        /// </summary>
        public static void WritePreviews(string folder)
        {
            foreach (var split in DatasetSplits.Names)
            {
                var dir = Path.Combine(folder, split);
                if (!Directory.Exists(dir)) continue;
                var files = Directory.GetFiles(dir, "r_*" + DatasetLayout.Suffix(DatasetFileKind.InstancePng))
                    .Select(f => new { File = f, Index = IndexOf(Path.GetFileName(f)) })
                    .Where(f => f.Index >= 0).OrderBy(f => f.Index).Take(LabelPreview.MaxViews).ToList();
                var maps = new List<ushort[]>();
                int width = 0, height = 0;
                foreach (var f in files)
                {
                    var map = PngGray16Reader.Read(f.File, out var w, out var h, "instance map");
                    if (maps.Count == 0)
                    {
                        width = w;
                        height = h;
                    }
                    if (w == width && h == height) maps.Add(map);
                }
                if (maps.Count == 0) continue;
                var png = LabelPreview.Encode(maps, width, height);
                FileOps.WriteNewBytes(Path.Combine(folder, DatasetLayout.LabelsPreviewFileName(split)), png);
            }
        }

        static int IndexOf(string name)
        {
            var digits = name.Substring(2, name.Length - 2 - DatasetLayout.Suffix(DatasetFileKind.InstancePng).Length);
            return int.TryParse(digits, System.Globalization.NumberStyles.None, System.Globalization.CultureInfo.InvariantCulture, out var index) ? index : -1;
        }
    }
}
