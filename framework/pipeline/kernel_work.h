#pragma once
// What one unit of a kernel's work costs (a cell-iteration, a VPL, a pixel, a surfel): the
// multiply-adds and the bytes read and written that its work model counts. The GL launchers'
// models (variants/**/*_gl.h) give these; a strategy's work report (WorkCount, strategy.h) and
// lpvlab-gpubench's rows carry them with their units.

namespace lpvlab {

struct KernelWork {
  double multiplyAdds = 0.0;
  double bytes = 0.0;
};

}  // namespace lpvlab
