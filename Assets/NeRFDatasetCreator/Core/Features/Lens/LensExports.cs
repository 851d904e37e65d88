using System.Collections.Generic;

namespace NerfDatasetCreator
{
    /// <summary>
    /// Where a distorted dataset's lens can go. nerfstudio holds both models (camera_model + k1…k4, p1, p2);
    /// instant-ngp holds OPENCV without k3 and a fisheye with some non-zero coefficient (<see cref="NgpWriter.Refusal"/>);
    /// COLMAP holds all of them (OPENCV, FULL_OPENCV, OPENCV_FISHEYE) but 3DGS's COLMAP reader asserts PINHOLE or
    /// SIMPLE_PINHOLE, so it warns; Dynamic 3D Gaussians' per-time-step files carry only a pinhole K and refuse.
    /// Without this the images of a distorted dataset would be exported under a pinhole camera and no longer match
    /// their rays.
    /// </summary>
    public static class LensExports
    {
        /// <summary>Why <paramref name="target"/> cannot take a dataset with <paramref name="lens"/>, or null when it can (always null for a pinhole).</summary>
        public static ValidationProblem Refusal(LensDistortion lens, ExportTarget target, bool depths = false)
        {
            if (lens == null) return null;
            switch (target)
            {
                case ExportTarget.Dynamic3dgs:
                    return new ValidationProblem("--to", "dynamic3dgs",
                        "cannot hold lens distortion: Dynamic 3D Gaussians' train_meta.json gives each camera a pinhole K only, and this dataset's images were taken through " + lens.Describe() + ".",
                        "Undistort the images to a pinhole first, or convert to nerfstudio, ngp or colmap, which carry the lens.");
                case ExportTarget.Ngp:
                    return NgpWriter.Refusal(lens);
                case ExportTarget.GaussianGrouping:
                    return new ValidationProblem("--to", "gaussian-grouping",
                        "cannot hold lens distortion: Gaussian Grouping's COLMAP reader accepts only PINHOLE and SIMPLE_PINHOLE cameras (scene/dataset_readers.py:83-93), and this dataset's images were taken through " + lens.Describe() + ".",
                        "Undistort the images to a pinhole first, or convert to nerfstudio or colmap, which carry the lens.");
                case ExportTarget.Replica:
                case ExportTarget.Tum:
                    return new ValidationProblem("--to", ExportTargets.Name(target),
                        "cannot hold lens distortion: SplaTAM and Gaussian-SLAM undistort the colour image only, not the depth (SplaTAM basedataset.py:308–310, Gaussian-SLAM datasets.py:155–157), so colour and depth would no longer align; the configs written describe a pinhole, and this dataset's images were taken through " + lens.Describe() + ".",
                        "Capture without a lens (the Camera step's lens \"none\") for a SLAM sequence.");
                case ExportTarget.HdrNerf:
                    return new ValidationProblem("--to", "hdr-nerf",
                        "cannot hold lens distortion: HDR-NeRF's synthetic loader takes a pinhole focal from camera_angle_x only (load_syn_llff.py:133–134), and this dataset's images were taken through " + lens.Describe() + ".",
                        "Capture without a lens (the Camera step's lens \"none\") for exposure brackets.");
                case ExportTarget.Tensoir:
                case ExportTarget.GsIr:
                case ExportTarget.R3dg:
                    return new ValidationProblem("--to", ExportTargets.Name(target),
                        "cannot hold lens distortion: TensoIR, NeRFactor, GS-IR and R3DG take a pinhole focal from cam_angle_x / camera_angle_x only (tensoIR_rotation_setting.py:103, nerf.py:188, dataset_readers.py:232, 557), and this dataset's images were taken through " + lens.Describe() + ".",
                        "Capture without a lens (the Camera step's lens \"none\") for inverse-rendering layouts.");
                case ExportTarget.Colmap when depths:
                    return new ValidationProblem("--depths", lens.ColmapModelName,
                        "writes depth maps for 3DGS, whose COLMAP reader accepts only PINHOLE and SIMPLE_PINHOLE cameras, and this dataset's lens is " + lens.Describe() + ".",
                        "Drop --depths (the model itself is written with its lens), or undistort the images first.");
                default:
                    return null;
            }
        }

        /// <summary>What a COLMAP export of a distorted dataset tells the user: 3DGS refuses the model (its tracks are projected through the lens: ColmapVisibility).</summary>
        public static ValidationProblem ColmapWarning(LensDistortion lens)
        {
            return new ValidationProblem("cameras", lens.ColmapModelName + " " + lens.Describe(),
                "is the camera the images were taken through; COLMAP, nerfstudio (ns-process-data / colmap dataparser) and gsplat read it, but 3DGS's COLMAP reader (scene/dataset_readers.py readColmapCameras) accepts only PINHOLE and SIMPLE_PINHOLE and stops with \"Colmap camera model not handled\".",
                "For 3DGS, undistort first (colmap image_undistorter --input_path sparse/0 --output_path <out>) and train on <out>.");
        }
    }
}
