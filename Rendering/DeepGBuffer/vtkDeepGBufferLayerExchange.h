/**
 * @class   vtkDeepGBufferLayerExchange
 * @brief   Composites the deep G-buffer's layers across the processes of a
 *          distributed render.
 *
 * When a scene is split across processes (ParaView's pvbatch or pvserver
 * under MPI), each process draws only its part of it. A deep G-buffer's
 * layer 1 is the nearest surface at least the minimum separation behind
 * layer 0 of the whole scene (paper section 2.1), which no process can peel
 * from its part alone. With an exchange set
 * (vtkDeepGBufferPass::SetLayerExchange), the G-buffer draws one geometry
 * pass per layer (DEPTH_PEEL) and hands each layer, once drawn, to
 * CompositeLayer: afterwards every process holds, per pixel, the values of
 * the process whose surface is nearest, and the next layer is peeled
 * against that composited layer (a distributed depth peel: one exchange
 * per layer). The effects then shade the same layers on every process.
 *
 * The processes must call CompositeLayer together: the pass calls it once
 * per layer and frame, also on a process with nothing to draw, so every
 * process must render the same frames at the same size and layer count
 * (vtkDeepGIPass's adaptive layer count is per process: switch it off).
 * Subclasses implement the transport (vtkPVDeepGILayerExchange of the
 * ParaView plugin uses the global vtkMultiProcessController).
 */

#ifndef vtkDeepGBufferLayerExchange_h
#define vtkDeepGBufferLayerExchange_h

#include "vtkDeepGIRenderingModule.h" // for export macro
#include "vtkObject.h"

#include <vector> // for std::vector

class VTKDEEPGIRENDERING_EXPORT vtkDeepGBufferLayerExchange : public vtkObject
{
public:
  vtkTypeMacro(vtkDeepGBufferLayerExchange, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Composites one layer of `pixels` pixels in place. `depth` holds the
   * layer's window depth per pixel (1 where nothing was drawn);
   * `attributes` the pixel's other quantities, `bytesPerPixel` bytes per
   * pixel. On return both hold, per pixel, the values of the process with
   * the smallest depth (the lowest process on ties), the same on every
   * process. Returns false when the exchange failed (the pass then warns
   * once and keeps this process's own layer).
   */
  virtual bool CompositeLayer(vtkIdType pixels, std::vector<float>& depth,
    std::vector<unsigned char>& attributes, int bytesPerPixel) = 0;

  /// Bytes this process sent in its CompositeLayer calls since the last
  /// ResetBytesSent (the cost of the compositing).
  vtkGetMacro(BytesSent, vtkTypeInt64);
  void ResetBytesSent() { this->BytesSent = 0; }

protected:
  vtkDeepGBufferLayerExchange() = default;
  ~vtkDeepGBufferLayerExchange() override = default;

  vtkTypeInt64 BytesSent = 0;

private:
  vtkDeepGBufferLayerExchange(const vtkDeepGBufferLayerExchange&) = delete;
  void operator=(const vtkDeepGBufferLayerExchange&) = delete;
};

#endif
