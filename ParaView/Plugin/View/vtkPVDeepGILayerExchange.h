/**
 * @class   vtkPVDeepGILayerExchange
 * @brief   The deep G-buffer's layer compositing over MPI, for ParaView's
 *          parallel render views.
 *
 * A vtkDeepGBufferLayerExchange on a vtkMultiProcessController (default:
 * the global one). Per layer, two all-reduce operations composite the
 * processes' layers by depth:
 * 1. the nearest process per pixel: the minimum over the processes of one
 *    64-bit key per pixel, the depth's IEEE-754 bits (which order as the
 *    depths do, all depths being non-negative) above the process id (which
 *    breaks ties towards the lowest process);
 * 2. its record: every process zeroes the records of the pixels it does not
 *    own, and the byte-wise maximum over the processes is then the owner's
 *    record, bit for bit.
 * Every process sends 8 + bytesPerPixel bytes per pixel and layer to each
 * reduction (BytesSent counts them); the result is exact and the same on
 * every process.
 */

#ifndef vtkPVDeepGILayerExchange_h
#define vtkPVDeepGILayerExchange_h

#include "vtkDeepGBufferLayerExchange.h"
#include "vtkDeepGIParaViewViewModule.h" // for export macro

class vtkMultiProcessController;

class VTKDEEPGIPARAVIEWVIEW_EXPORT vtkPVDeepGILayerExchange : public vtkDeepGBufferLayerExchange
{
public:
  static vtkPVDeepGILayerExchange* New();
  vtkTypeMacro(vtkPVDeepGILayerExchange, vtkDeepGBufferLayerExchange);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The processes to composite over; null (default): the global controller.
  void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);

  bool CompositeLayer(vtkIdType pixels, std::vector<float>& depth,
    std::vector<unsigned char>& attributes, int bytesPerPixel) override;

protected:
  vtkPVDeepGILayerExchange() = default;
  ~vtkPVDeepGILayerExchange() override;

private:
  vtkPVDeepGILayerExchange(const vtkPVDeepGILayerExchange&) = delete;
  void operator=(const vtkPVDeepGILayerExchange&) = delete;

  vtkMultiProcessController* Controller = nullptr;
};

#endif
