#include "study/row_study.hpp"

#include "study/foundation_options.hpp"
#include "study/sears_row_options.hpp"

namespace pound {

RowStudy read_row_study(const Options& opt, const StudyUseOf& use_of) {
  RowStudy s;
  s.row = row_from_options(opt);
  StudyUse use_all;
  if (use_of)
    use_all = use_of(s.row);
  else
    use_all.contact = single_model_use(opt);
  const ContactUse& use = use_all.contact;
  s.ground = ground_from_options(opt, s.row, use_all.sampled_velocity);
  s.contact = contact_from_options(opt, s.row, use);
  if (use.sears()) {
    s.has_sears = true;
    s.sears = sears_row_from_options(opt, s.row);
  }
  s.integrator = integrator_from_options(opt);
  s.simulation = simulation_from_options(opt);
  return s;
}

}  // namespace pound
