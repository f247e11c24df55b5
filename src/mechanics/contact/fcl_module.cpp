// libraryContacts as a call into the FCL module (docs/architecture.md, "FCL module"): the module
// (fcl_narrow_phase.cpp, built as openmss_fcl.so) is opened on the first call, so a process
// whose models have no FCL pair never loads libfcl.

#include "user/fcl_module.hpp"

#include <stdexcept>
#include <string>

#include "mechanics/contact/fcl_narrow_phase.hpp"
#include "user/user_library.hpp"

namespace openmss::mechanics::contact {

void libraryContacts(const model::ContactSolid& si, const SolidFrame<double>& fi,
                     const model::ContactSolid& sj, const SolidFrame<double>& fj,
                     std::vector<LibraryContact>& out) {
  static const auto entry = [] {
    std::string why;
    auto* f = user::asFunction<LibraryContactsEntry>(user::fclModuleEntry(why));
    // The model builder refuses a CONTACT whose pair needs the module when it does not load
    // (contact_builder.cpp), so this is reached only by a model built another way.
    if (!f) throw std::runtime_error("the FCL narrow phase module did not load: " + why);
    return f;
  }();
  entry(&si, &fi, &sj, &fj, &out);
}

}  // namespace openmss::mechanics::contact
