using System;
using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>How a trainer writes its renders of a split (see <see cref="RenderFolder"/> and Documentation~/evaluate.md).</summary>
    public enum RenderLayout
    {
        /// <summary>3DGS <c>render.py</c>: <c>&lt;model&gt;/&lt;split&gt;/ours_&lt;iter&gt;/renders/00000.png</c>, in the split's frame order.</summary>
        GaussianSplatting,

        /// <summary>nerfstudio <c>ns-render dataset</c>: <c>&lt;out&gt;/&lt;split&gt;/rgb/r_0.png</c>, optional <c>raw-depth/r_0.npy.gz</c>, <c>raw-normals/…</c>.</summary>
        Nerfstudio,

        /// <summary>instant-ngp <c>scripts/run.py --screenshot_transforms</c>: <c>&lt;dir&gt;/r_0.png</c> (RGBA), named by each frame's file_path.</summary>
        InstantNgp,

        /// <summary>A plain folder of <c>r_&lt;i&gt;.png</c>, optional <c>r_&lt;i&gt;_depth_0000.png</c> and <c>r_&lt;i&gt;_normal_0000.png</c> in this plugin's encodings.</summary>
        Plain,

        /// <summary>nerf-pytorch <c>run_nerf.py</c>: <c>&lt;basedir&gt;/&lt;expname&gt;/testset_&lt;iter&gt;/000.png</c> (or <c>renderonly_test_&lt;iter&gt;/</c>), the test split's frames in file order.</summary>
        NerfPytorch,
    }

    public static class RenderLayouts
    {
        public static readonly IReadOnlyList<string> Names = new[] { "3dgs", "nerfstudio", "ngp", "plain", "nerf-pytorch" };

        public static string Name(RenderLayout layout)
        {
            switch (layout)
            {
                case RenderLayout.GaussianSplatting: return "3dgs";
                case RenderLayout.Nerfstudio: return "nerfstudio";
                case RenderLayout.InstantNgp: return "ngp";
                case RenderLayout.NerfPytorch: return "nerf-pytorch";
                default: return "plain";
            }
        }

        public static bool TryParse(string name, out RenderLayout layout)
        {
            for (var i = 0; i < Names.Count; i++)
                if (string.Equals(Names[i], name, StringComparison.OrdinalIgnoreCase))
                {
                    layout = (RenderLayout)i;
                    return true;
                }
            layout = RenderLayout.Plain;
            return false;
        }

        /// <summary>Where the trainer's code says so (the file and line this reading follows).</summary>
        public static string Source(RenderLayout layout)
        {
            switch (layout)
            {
                case RenderLayout.GaussianSplatting:
                    return "graphdeco-inria/gaussian-splatting render.py (182afc9) lines 30-46: <model>/<split>/ours_<iter>/renders/'{0:05d}'.format(idx).png over scene.getTestCameras() in the split file's order (Scene(..., shuffle=False), line 51), RGB via torchvision save_image; with --train_test_exp the right half only (lines 41-43)";
                case RenderLayout.Nerfstudio:
                    return "nerfstudio-project/nerfstudio nerfstudio/scripts/render.py (50e0e3c) lines 783, 829-831, 882-888: <output-path>/<split>/<output name>/<image path relative to the split's common folder>, .png only with --image-format png (line 418: default jpeg), raw-* outputs as .npy.gz (line 845: raw depth divided by the dataparser scale)";
                case RenderLayout.InstantNgp:
                    return "NVlabs/instant-ngp scripts/run.py (abe236e) lines 343-352: <screenshot_dir>/basename(file_path) + .png when extensionless; scripts/common.py lines 149-164: RGBA, alpha un-multiplied, sRGB";
                case RenderLayout.NerfPytorch:
                    return "yenchenlin/nerf-pytorch run_nerf.py (63a5a63) lines 818-822: <basedir>/<expname>/testset_{:06d}/ over poses[i_test], and lines 622-623, 657-664: renderonly_test_{:06d}/ with --render_only --render_test; lines 166-169: '{:03d}'.format(i).png, RGB 8-bit, over white with --white_bkgd (lines 302-303); load_blender.py lines 51-56: the test split is frames[::testskip] in file order";
                default:
                    return "this plugin: r_<i>.png named by each frame's file_path, optional r_<i>_depth_0000.png (16-bit, thousandths of an output unit) and r_<i>_normal_0000.png (8-bit, output world frame)";
            }
        }
    }
}
