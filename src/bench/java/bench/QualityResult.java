package bench;

/**
 * The measured quality of one {@link QualityCase} against the scene's reference render.
 *
 * @param c              the case
 * @param psnr           peak signal-to-noise ratio over the 8-bit RGB channels, in dB (infinite when identical)
 * @param offShare       the share of pixels with some channel off by more than 8/255
 * @param cameraPerPixel camera rays per pixel
 * @param raysPerPixel   all rays (camera, shadow, secondary) per pixel
 * @param seconds        the render time (render loop only) of the timed run
 */
record QualityResult(QualityCase c, double psnr, double offShare, double cameraPerPixel, double raysPerPixel,
                     double seconds) {
}
